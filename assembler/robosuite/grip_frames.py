"""The frames and sensors robosuite looks a gripper up by, added where a gripper's model file has none.

robosuite's ``GripperModel`` reads the quaternion of a body named ``eef``; its robots find the
end-effector site by the names ``grip_site`` and ``grip_site_cylinder`` (``fixed_base_robot.py``
and ``mobile_robot.py``; the controllers take ``grip_site`` as their reference) and read the
``force_ee`` and ``torque_ee`` sensors at every control step (``Robot.ee_force``). robosuite's own
grippers carry all of them in their XML; a gripper from a URDF or a hand-written MJCF often has
none. For robosuite only, the gripper's ``eef_body`` then gets a child body ``eef`` at its origin
and the two sites, and its root body a site ``ft_frame`` with the force and torque sensors, all as
robosuite's grippers define them; our own builds are unchanged. The additions are said once per
process (an :class:`~assembler.errors.AssemblerWarning`) and ``lint`` reports them (RA702).
"""

from __future__ import annotations

import mujoco

from assembler import models
from assembler.robosuite.conventions import EEF, GRIP_CYLINDER, GRIP_SENSORS, GRIP_SITE, grip_sensors
from assembler.spec.fieldpath import FieldPath

FT_FRAME = "ft_frame"


def _missing_sensors(gripper: models.GripperModel, mjspec: mujoco.MjSpec) -> list[str]:
    names = (name for _, name in grip_sensors(gripper.spec.important_sensors))
    return [name for name in names if mjspec.sensor(name) is None]


def missing_grip_frames(gripper: models.GripperModel, mjspec: mujoco.MjSpec) -> list[str]:
    """The names robosuite looks up that ``mjspec`` (the gripper's part spec) lacks."""
    missing = [] if mjspec.body(EEF) is not None else [f"body '{EEF}'"]
    missing += [f"site '{name}'" for name in (GRIP_SITE, GRIP_CYLINDER) if mjspec.site(name) is None]
    return missing + [f"sensor '{name}'" for name in _missing_sensors(gripper, mjspec)]


def add_grip_frames(gripper: models.GripperModel, mjspec: mujoco.MjSpec) -> None:
    """Give ``mjspec`` robosuite's ``eef`` body and grip sites where it has none (see the module)."""
    missing = missing_grip_frames(gripper, mjspec)
    if not missing:
        return
    _add_sensors(gripper, mjspec)
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
    gripper.warn(
        FieldPath(("eef_body",)),
        f"{gripper.spec.name}: robosuite looks a gripper up by {', '.join(missing)}, which its model "
        f"file lacks; added for robosuite (frames at body '{gripper.spec.eef_body}', sensors at its "
        "root body; add them to the model file to place them yourself)",
    )


def _add_sensors(gripper: models.GripperModel, mjspec: mujoco.MjSpec) -> None:
    """robosuite's force and torque sensors on a site ``ft_frame`` at the gripper's root body."""
    missing = _missing_sensors(gripper, mjspec)
    if not missing:
        return
    if mjspec.site(FT_FRAME) is None:
        mjspec.worldbody.first_body().add_site(
            name=FT_FRAME, size=[0.01, 0.01, 0.01], rgba=[1, 0, 0, 1], group=1
        )
    for role, kind in GRIP_SENSORS.items():
        name = gripper.spec.important_sensors.get(role, role)
        if name in missing:
            mjspec.add_sensor(name=name, type=kind, objtype=mujoco.mjtObj.mjOBJ_SITE, objname=FT_FRAME)
