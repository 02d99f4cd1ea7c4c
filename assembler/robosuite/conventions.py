"""What robosuite 1.5.2 asks of a spec robot and gripper, stated without importing robosuite.

``assembler lint`` checks robots against robosuite's needs (RA701-RA704) where robosuite may not be
installed, so it cannot import the bridge (:mod:`assembler.robosuite` imports robosuite first). The
bridge reads its robot types, driven groups and actuators, grip frames and sensor roles from here too,
so lint and bridge cannot disagree.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING

import mujoco

from assembler import models
from assembler.models.registering import REGISTRIES
from assembler.spec.fieldpath import FieldPath

if TYPE_CHECKING:  # a spec's type only: asking these questions of a recorded part imports no schema
    from assembler.spec.schema import RobotSpec

BY_BASE_TYPE: dict[str, str] = {
    "mount": "FixedBaseRobot",
    "null": "FixedBaseRobot",
    "mobile": "WheeledRobot",
    "legged": "LeggedRobot",
}
"""robosuite's Robot class for a robot standing on a base of each type."""

LEGGED_MORPHOLOGIES: frozenset[str] = frozenset({"legged_manipulator", "humanoid"})
"""Morphologies robosuite drives as a LeggedRobot whatever their base."""

DRIVEN_GROUPS: dict[str, tuple[str, ...]] = {
    "FixedBaseRobot": ("right", "left"),
    "WheeledRobot": ("right", "left", "torso", "head"),
    "LeggedRobot": ("right", "left", "torso", "head", "legs"),
}
"""The joint groups each Robot class drives with controllers that write torques into ``ctrl``."""

ACTUATION = FieldPath(("robosuite", "actuation"))
"""The spec field saying how robosuite's controllers drive a robot's position servos."""

CONTROLLER = FieldPath(("robosuite", "controller"))
"""The spec field naming a robot's controller configuration for robosuite."""

INERTIA_GROUPS = (0, 0)
"""The geom groups robosuite's world (``models/assets/base.xml``) counts in inferred inertias
(``<compiler inertiagrouprange="0 0">``)."""

EEF = "eef"
GRIP_SITE = "grip_site"
GRIP_CYLINDER = "grip_site_cylinder"

GRIP_FRAMES: tuple[tuple[mujoco.mjtObj, str], ...] = (
    (mujoco.mjtObj.mjOBJ_BODY, EEF),
    (mujoco.mjtObj.mjOBJ_SITE, GRIP_SITE),
    (mujoco.mjtObj.mjOBJ_SITE, GRIP_CYLINDER),
)
"""The body and sites robosuite looks a gripper up by (its GripperModel and its robots)."""

GRIP_SENSORS: dict[str, mujoco.mjtSensor] = {
    "force_ee": mujoco.mjtSensor.mjSENS_FORCE,
    "torque_ee": mujoco.mjtSensor.mjSENS_TORQUE,
}
"""The end-effector sensors robosuite's robots read at every step (``Robot.ee_force``/``ee_torque``),
by role, with the sensor type of each."""


def grip_sensors(important_sensors: dict[str, str]) -> list[tuple[mujoco.mjtObj, str]]:
    """The sensors robosuite reads of a gripper whose spec names ``important_sensors``."""
    return [(mujoco.mjtObj.mjOBJ_SENSOR, important_sensors.get(role, role)) for role in GRIP_SENSORS]


AFFINE = int(mujoco.mjtBias.mjBIAS_AFFINE)
FIXED = int(mujoco.mjtGain.mjGAIN_FIXED)


def is_servo(gaintype: int, biastype: int, bias_position: float) -> bool:
    """A servo towards a position target (MuJoCo's ``<position>``): fixed gain, bias -kp times the length."""
    return int(gaintype) == FIXED and int(biastype) == AFFINE and bias_position < 0


def limits_force(limited: bool, forcerange: Sequence[float]) -> bool:
    """Whether an actuator limits its force to a non-empty range (the range its motor would take as
    ctrlrange)."""
    low, high = (float(value) for value in forcerange)
    return limited and low < high


def base_in_robosuite(spec: RobotSpec) -> str:
    """The base a spec robot stands on in robosuite: its default base, else its stand-in (declared, or
    by morphology: see ``RobosuiteOptions.stand_in_base``)."""
    if spec.default_base is not None:
        return spec.default_base
    if spec.robosuite.stand_in_base is not None:
        return spec.robosuite.stand_in_base
    return "NoActuationBase" if spec.morphology in LEGGED_MORPHOLOGIES else "NullMount"


def robot_type_name(robot_class: type[models.ManipulatorModel]) -> str:
    """robosuite's Robot class for ``robot_class`` (FixedBaseRobot, WheeledRobot or LeggedRobot, the
    only ones robosuite's environments accept): declared, else by morphology and base. The class
    decides which body parts get controllers (``DRIVEN_GROUPS``)."""
    spec = robot_class.spec
    if spec.robosuite.robot_type is not None:
        return str(spec.robosuite.robot_type)
    if spec.morphology in LEGGED_MORPHOLOGIES:
        return "LeggedRobot"
    base = REGISTRIES["base"].get(base_in_robosuite(spec))
    return BY_BASE_TYPE[base.spec.type] if base is not None else "FixedBaseRobot"


def driven_actuators(robot: models.ManipulatorModel) -> list[str]:
    """The robot's own actuators (prefixed, in group order) that robosuite's controllers drive."""
    groups = robot.actuator_groups()
    named = [name for group in DRIVEN_GROUPS[robot_type_name(type(robot))] for name in groups.get(group, [])]
    return [name for name in named if name.startswith(robot.naming_prefix)]


def is_bridge_servo(model: mujoco.MjModel, actuator: int) -> bool:
    """A compiled actuator the bridge reads as a position servo (:func:`is_servo`)."""
    kind = (model.actuator_gaintype[actuator], model.actuator_biastype[actuator])
    return is_servo(*kind, float(model.actuator_biasprm[actuator, 1]))


def has_force_range(model: mujoco.MjModel, actuator: int) -> bool:
    """Whether a compiled actuator limits its force (:func:`limits_force`)."""
    return limits_force(bool(model.actuator_forcelimited[actuator]), model.actuator_forcerange[actuator])


def arm_center_site(arm: str) -> str:
    """The site robosuite's composite controller reads as an arm's origin (unprefixed)."""
    return f"{arm}_center"


def offered(spec_class: type[models.PartModel]) -> bool:
    """Whether a spec class enters robosuite: every gripper and base; a robot unless its spec says
    ``robosuite.enabled: false`` or it has no arms (``morphology: legged``: robosuite's robots are
    manipulators). A question about the spec alone: asking it imports no robosuite."""
    if not issubclass(spec_class, models.ManipulatorModel):
        return True
    return spec_class.spec.robosuite.enabled and bool(spec_class.spec.arms)
