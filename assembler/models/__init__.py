"""Robot model classes by morphology; spec-made classes derive from one of these."""

from assembler.models.manipulator import ManipulatorModel
from assembler.models.robot_model import RobotModel

MORPHOLOGY_CLASSES: dict[str, type[RobotModel]] = {
    "manipulator": ManipulatorModel,
}
"""The model class each spec ``morphology`` becomes a subclass of."""

__all__ = ["MORPHOLOGY_CLASSES", "ManipulatorModel", "RobotModel"]
