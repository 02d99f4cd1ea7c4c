"""The ``{arm}_center`` sites robosuite's arm controllers read, added where a robot's model file has none.

robosuite's OSC controller reads the velocity of the site ``{prefix}{arm}_center`` (the frame the
arm is mounted in) at every step; robosuite's robots carry one per arm on the body holding the
arm's first link (Panda: ``link0``). A robot from a URDF or a hand-written MJCF often has none. For
robosuite only, such an arm gets the site on the body its first joint's link hangs from, as
robosuite's robots define it; our own builds are unchanged. The addition is said once per process
and ``lint`` reports it.
"""

from __future__ import annotations

import mujoco

from assembler import models
from assembler.robosuite.conventions import arm_center_site
from assembler.spec.fieldpath import FieldPath


def arms_without_center(robot: models.ManipulatorModel, mjspec: mujoco.MjSpec) -> list[str]:
    """The arms (with joints) whose ``{arm}_center`` site ``mjspec``, the robot's part spec, lacks."""
    groups = robot.arm_joints
    return [arm for arm in robot.arms if groups[arm] and mjspec.site(arm_center_site(arm)) is None]


def add_arm_centers(robot: models.ManipulatorModel, mjspec: mujoco.MjSpec) -> None:
    """Give ``mjspec`` robosuite's ``{arm}_center`` site for every arm that has none (see the module)."""
    arms = arms_without_center(robot, mjspec)
    for arm in arms:
        first_joint = robot.arm_joints[arm][0].removeprefix(robot.naming_prefix)
        link = mjspec.joint(first_joint).parent
        mount = link.parent if link.parent.name != "world" else link
        mount.add_site(name=arm_center_site(arm), size=[0.01, 0.01, 0.01], rgba=[1, 0.3, 0.3, 1], group=2)
    missing = [arm_center_site(arm) for arm in arms]
    if missing:
        robot.warn(
            FieldPath((robot.spec.source_field,)),
            f"{robot.spec.name}: robosuite's arm controllers read the site{'s' if len(missing) > 1 else ''} "
            f"{', '.join(missing)}, which "
            "the model file lacks; added for robosuite on the body each arm's first link hangs from (add "
            "them to the model file to place them yourself)",
        )
