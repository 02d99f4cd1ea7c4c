"""Robot, base and gripper model classes; spec-made classes derive from one of these."""

from assembler.models.base_model import RobotBaseModel
from assembler.models.gripper_model import GripperModel
from assembler.models.manipulator import (
    HumanoidModel,
    HumanoidUpperBodyModel,
    LeggedManipulatorModel,
    ManipulatorModel,
)
from assembler.models.part import PartModel
from assembler.models.robot_model import RobotModel

MORPHOLOGY_CLASSES: dict[str, type[RobotModel]] = {
    "manipulator": ManipulatorModel,
    "legged_manipulator": LeggedManipulatorModel,
    "humanoid": HumanoidModel,
    "humanoid_upper_body": HumanoidUpperBodyModel,
}
"""The model class each robot spec's ``morphology`` becomes a subclass of."""

KIND_CLASSES: dict[str, type[PartModel]] = {"base": RobotBaseModel, "gripper": GripperModel}
"""The model class base and gripper specs become subclasses of."""

__all__ = [
    "KIND_CLASSES",
    "MORPHOLOGY_CLASSES",
    "GripperModel",
    "HumanoidModel",
    "HumanoidUpperBodyModel",
    "LeggedManipulatorModel",
    "ManipulatorModel",
    "PartModel",
    "RobotBaseModel",
    "RobotModel",
]
