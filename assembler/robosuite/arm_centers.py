"""The ``{arm}_center`` sites robosuite's arm controllers read, added where a robot's model file has none.

robosuite's OSC controller reads the velocity of the site ``{prefix}{arm}_center`` (the frame the
arm is mounted in) at every step; robosuite's robots carry one per arm on the body holding the
arm's first link (Panda: ``link0``). A robot from a URDF or a hand-written MJCF often has none. For
robosuite only, such an arm gets the site on the body its first joint's link hangs from, as
robosuite's robots define it; our own builds are unchanged. The addition is said once per process
and ``lint`` reports it.
"""

from __future__ import annotations

import warnings

import mujoco

from assembler.errors import AssemblerWarning
from assembler.models import ManipulatorModel


def missing_arm_centers(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> list[str]:
    """The ``{arm}_center`` sites ``mjspec`` (the robot's unprefixed part spec) lacks, per arm with joints."""
    groups = robot.arm_joints
    return [f"{arm}_center" for arm in robot.arms if groups[arm] and mjspec.site(f"{arm}_center") is None]


def add_arm_centers(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> None:
    """Give ``mjspec`` robosuite's ``{arm}_center`` site for every arm that has none (see the module)."""
    missing = missing_arm_centers(robot, mjspec)
    for name in missing:
        arm = name.removesuffix("_center")
        first_joint = robot.arm_joints[arm][0].removeprefix(robot.naming_prefix)
        link = mjspec.joint(first_joint).parent
        mount = link.parent if link.parent.name != "world" else link
        mount.add_site(name=name, size=[0.01, 0.01, 0.01], rgba=[1, 0.3, 0.3, 1], group=2)
    if missing:
        warnings.warn(
            f"{robot.spec.name}: robosuite's arm controllers read the site{'s' if len(missing) > 1 else ''} "
            f"{', '.join(missing)}, which "
            "the model file lacks; added for robosuite on the body each arm's first link hangs from (add "
            "them to the model file to place them yourself)",
            AssemblerWarning,
            stacklevel=2,
        )
