"""The frames robosuite looks a gripper up by, added where a gripper's model file has none.

robosuite's ``GripperModel`` reads the quaternion of a body named ``eef``, and its robots find the
end-effector site by the names ``grip_site`` and ``grip_site_cylinder`` (``fixed_base_robot.py``
and ``mobile_robot.py``; the controllers take ``grip_site`` as their reference). robosuite's own
grippers carry all three in their XML; a gripper from a URDF or a hand-written MJCF often has none.
For robosuite only, the gripper's ``eef_body`` then gets a child body ``eef`` at its origin and the
two sites as robosuite's grippers define them; our own builds are unchanged. Each addition is said
once per process (an :class:`~assembler.errors.AssemblerWarning`) and ``lint`` reports it (RA702).
"""

from __future__ import annotations

import warnings

import mujoco

from assembler.errors import AssemblerWarning
from assembler.models import GripperModel

EEF = "eef"
GRIP_SITE = "grip_site"
GRIP_CYLINDER = "grip_site_cylinder"


def missing_grip_frames(mjspec: mujoco.MjSpec) -> list[str]:
    """The names robosuite looks up that ``mjspec`` (a gripper's part spec) lacks."""
    missing = [] if mjspec.body(EEF) is not None else [f"body '{EEF}'"]
    return missing + [f"site '{name}'" for name in (GRIP_SITE, GRIP_CYLINDER) if mjspec.site(name) is None]


def add_grip_frames(gripper: GripperModel, mjspec: mujoco.MjSpec) -> None:
    """Give ``mjspec`` robosuite's ``eef`` body and grip sites where it has none (see the module)."""
    missing = missing_grip_frames(mjspec)
    if not missing:
        return
    eef = mjspec.body(EEF)
    if eef is None:
        eef = mjspec.body(gripper.spec.eef_body).add_body(name=EEF)
    if mjspec.site(GRIP_SITE) is None:
        eef.add_site(
            name=GRIP_SITE,
            type=mujoco.mjtGeom.mjGEOM_SPHERE,
            size=[0.01, 0.01, 0.01],
            rgba=[1, 0, 0, 0.5],
            group=1,
        )
    if mjspec.site(GRIP_CYLINDER) is None:
        eef.add_site(
            name=GRIP_CYLINDER,
            type=mujoco.mjtGeom.mjGEOM_CYLINDER,
            size=[0.005, 10, 0],
            rgba=[0, 1, 0, 0.3],
            group=1,
        )
    warnings.warn(
        f"{gripper.spec.name}: robosuite looks a gripper up by {', '.join(missing)}, which its model "
        f"file lacks; added at body '{gripper.spec.eef_body}' for robosuite (add them to the model file "
        "to place them yourself)",
        AssemblerWarning,
        stacklevel=2,
    )
