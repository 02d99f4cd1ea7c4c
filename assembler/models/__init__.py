"""Robot, base and gripper model classes; spec-made classes derive from one of these."""

from assembler.models.bases import (
    BASE_TYPE_CLASSES,
    REGISTERED_BASES,
    LegBaseModel,
    MobileBaseModel,
    MountModel,
    NullBaseModel,
    RobotBaseModel,
)
from assembler.models.gripper_model import REGISTERED_GRIPPERS, GripperModel
from assembler.models.manipulator import (
    HumanoidModel,
    HumanoidUpperBodyModel,
    LeggedManipulatorModel,
    LeggedModel,
    ManipulatorModel,
)
from assembler.models.part import PartModel
from assembler.models.registering import RegisteringMeta, Registry, source_of
from assembler.models.robot_model import REGISTERED_ROBOTS, RobotModel

MORPHOLOGY_CLASSES: dict[str, type[RobotModel]] = {
    "manipulator": ManipulatorModel,
    "legged_manipulator": LeggedManipulatorModel,
    "humanoid": HumanoidModel,
    "humanoid_upper_body": HumanoidUpperBodyModel,
    "legged": LeggedModel,
}
"""The model class each robot spec's ``morphology`` becomes a subclass of."""

REGISTRIES: dict[str, Registry[PartModel]] = {
    "robot": REGISTERED_ROBOTS,  # type: ignore[dict-item]
    "base": REGISTERED_BASES,  # type: ignore[dict-item]
    "gripper": REGISTERED_GRIPPERS,  # type: ignore[dict-item]
}
"""Each family's registry."""

__all__ = [
    "BASE_TYPE_CLASSES",
    "MORPHOLOGY_CLASSES",
    "REGISTERED_BASES",
    "REGISTERED_GRIPPERS",
    "REGISTERED_ROBOTS",
    "REGISTRIES",
    "GripperModel",
    "HumanoidModel",
    "HumanoidUpperBodyModel",
    "LegBaseModel",
    "LeggedManipulatorModel",
    "LeggedModel",
    "ManipulatorModel",
    "MobileBaseModel",
    "MountModel",
    "NullBaseModel",
    "PartModel",
    "RegisteringMeta",
    "Registry",
    "RobotBaseModel",
    "RobotModel",
    "source_of",
]
