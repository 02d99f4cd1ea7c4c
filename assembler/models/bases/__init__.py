"""Base types, one class each; a base spec's ``type`` picks the class its spec-made class derives from."""

from assembler.models.bases.base import REGISTERED_BASES, RobotBaseModel
from assembler.models.bases.legged import LegBaseModel
from assembler.models.bases.mobile import MobileBaseModel
from assembler.models.bases.mount import MountModel
from assembler.models.bases.null import NullBaseModel

BASE_TYPE_CLASSES: dict[str, type[RobotBaseModel]] = {
    "mount": MountModel,
    "mobile": MobileBaseModel,
    "legged": LegBaseModel,
    "null": NullBaseModel,
}
"""The class each base spec's ``type`` becomes a subclass of."""

__all__ = [
    "BASE_TYPE_CLASSES",
    "REGISTERED_BASES",
    "LegBaseModel",
    "MobileBaseModel",
    "MountModel",
    "NullBaseModel",
    "RobotBaseModel",
]
