"""Robot, base and gripper model classes; spec-made classes derive from one of these.

Each name is imported from its module on first use (:data:`HOMES`), so importing this package, or
its registries alone (:mod:`.registering`), imports neither the classes nor the schema they are made
of: robosuite's bridge reads the registries at every import, and a warm ``robosuite.make`` of
recorded parts never needs a class (``tests/robosuite/test_warm_make.py``). The imports under
``TYPE_CHECKING`` repeat the table for type checkers; a test holds the two equal.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

if TYPE_CHECKING:  # for type checkers and editors: HOMES below, as imports (a test holds them equal)
    from assembler.models.bases import BASE_TYPE_CLASSES as BASE_TYPE_CLASSES
    from assembler.models.bases import REGISTERED_BASES as REGISTERED_BASES
    from assembler.models.bases import LegBaseModel as LegBaseModel
    from assembler.models.bases import MobileBaseModel as MobileBaseModel
    from assembler.models.bases import MountModel as MountModel
    from assembler.models.bases import NullBaseModel as NullBaseModel
    from assembler.models.bases import RobotBaseModel as RobotBaseModel
    from assembler.models.gripper_model import REGISTERED_GRIPPERS as REGISTERED_GRIPPERS
    from assembler.models.gripper_model import GripperModel as GripperModel
    from assembler.models.manipulator import MORPHOLOGY_CLASSES as MORPHOLOGY_CLASSES
    from assembler.models.manipulator import HumanoidModel as HumanoidModel
    from assembler.models.manipulator import HumanoidUpperBodyModel as HumanoidUpperBodyModel
    from assembler.models.manipulator import LeggedManipulatorModel as LeggedManipulatorModel
    from assembler.models.manipulator import LeggedModel as LeggedModel
    from assembler.models.manipulator import ManipulatorModel as ManipulatorModel
    from assembler.models.part import PartModel as PartModel
    from assembler.models.registering import REGISTRIES as REGISTRIES
    from assembler.models.registering import RegisteringMeta as RegisteringMeta
    from assembler.models.registering import Registry as Registry
    from assembler.models.registering import source_of as source_of
    from assembler.models.robot_model import REGISTERED_ROBOTS as REGISTERED_ROBOTS
    from assembler.models.robot_model import RobotModel as RobotModel

HOMES: dict[str, tuple[str, ...]] = {
    "assembler.models.bases": (
        "BASE_TYPE_CLASSES",
        "REGISTERED_BASES",
        "LegBaseModel",
        "MobileBaseModel",
        "MountModel",
        "NullBaseModel",
        "RobotBaseModel",
    ),
    "assembler.models.gripper_model": ("REGISTERED_GRIPPERS", "GripperModel"),
    "assembler.models.manipulator": (
        "MORPHOLOGY_CLASSES",
        "HumanoidModel",
        "HumanoidUpperBodyModel",
        "LeggedManipulatorModel",
        "LeggedModel",
        "ManipulatorModel",
    ),
    "assembler.models.part": ("PartModel",),
    "assembler.models.registering": ("REGISTRIES", "RegisteringMeta", "Registry", "source_of"),
    "assembler.models.robot_model": ("REGISTERED_ROBOTS", "RobotModel"),
}
"""Each module of the package and the names it gives, imported on first use."""

_SOURCES = {name: module for module, names in HOMES.items() for name in names}

__all__ = sorted(_SOURCES)


def __getattr__(name: str) -> Any:
    if name not in _SOURCES:
        raise AttributeError(f"module 'assembler.models' has no attribute '{name}'")
    try:
        module = importlib.import_module(_SOURCES[name])
    except AttributeError as error:
        # Raised while importing (MuJoCo starting an OpenGL backend that cannot load): passed on as
        # is, `from assembler.models import X` would report "cannot import name X" instead.
        raise ImportError(str(error)).with_traceback(error.__traceback__) from error
    value = getattr(module, name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    return sorted({*globals(), *_SOURCES})
