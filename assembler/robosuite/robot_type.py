"""Which of robosuite's Robot classes drives a spec robot: FixedBaseRobot, WheeledRobot or LeggedRobot.

robosuite picks the class by the robot's name (``ROBOT_CLASS_MAPPING``) and the environments accept
only these three. The class decides which body parts get controllers: FixedBaseRobot drives arms and
grippers only, WheeledRobot adds the base, torso and head, LeggedRobot also the legs (and sets their
initial positions from a legged base). A spec's ``robosuite.robot_type`` says it outright; otherwise
it follows the base robosuite stands the robot on and the robot's morphology.
"""

from __future__ import annotations

from assembler.models import REGISTERED_BASES, ManipulatorModel
from assembler.schema import RobotSpec

BY_BASE_TYPE: dict[str, str] = {
    "mount": "FixedBaseRobot",
    "null": "FixedBaseRobot",
    "mobile": "WheeledRobot",
    "legged": "LeggedRobot",
}

LEGGED_MORPHOLOGIES: frozenset[str] = frozenset({"legged_manipulator", "humanoid"})

DRIVEN_GROUPS: dict[str, tuple[str, ...]] = {
    "FixedBaseRobot": ("right", "left"),
    "WheeledRobot": ("right", "left", "torso", "head"),
    "LeggedRobot": ("right", "left", "torso", "head", "legs"),
}
"""The joint groups robosuite's Robot class drives with controllers that write torques (a base's take
velocities)."""


def base_in_robosuite(spec: RobotSpec) -> str:
    """The base a spec robot stands on in robosuite: its default base, else its stand-in (declared, or
    by morphology: see ``RobosuiteOptions.stand_in_base``)."""
    if spec.default_base is not None:
        return spec.default_base
    if spec.robosuite.stand_in_base is not None:
        return spec.robosuite.stand_in_base
    return "NoActuationBase" if spec.morphology in LEGGED_MORPHOLOGIES else "NullMount"


def robot_type_name(robot_class: type[ManipulatorModel]) -> str:
    """The name of robosuite's Robot class for ``robot_class`` (declared, or by base and morphology)."""
    spec = robot_class.spec
    if spec.robosuite.robot_type is not None:
        return str(spec.robosuite.robot_type)
    if spec.morphology in LEGGED_MORPHOLOGIES:
        return "LeggedRobot"
    base = REGISTERED_BASES.get(base_in_robosuite(spec))
    return BY_BASE_TYPE[base.spec.type] if base is not None else "FixedBaseRobot"
