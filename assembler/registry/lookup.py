"""The registries of robots, bases and grippers, by name: registering, looking up, listing.

The tables and the registering metaclass live with the model classes
(:mod:`assembler.models.registering`); this module is the public face robosuite users expect
(``REGISTERED_ROBOTS``, ``register_robot``, ``RobotModelMeta``).
"""

from __future__ import annotations

from typing import Any

from assembler.errors import RegistryError, did_you_mean, summarize_names
from assembler.models import (
    REGISTERED_BASES,
    REGISTERED_GRIPPERS,
    REGISTERED_ROBOTS,
    REGISTRIES,
    GripperModel,
    PartModel,
    RegisteringMeta,
    RobotBaseModel,
    RobotModel,
    source_of,
)
from assembler.registry.catalog import PARENTS  # the shipped specs are registered with the catalog

__all__ = [
    "PARENTS",
    "REGISTERED_BASES",
    "REGISTERED_GRIPPERS",
    "REGISTERED_ROBOTS",
    "RobotModelMeta",
    "find_registered",
    "register_base",
    "register_gripper",
    "register_robot",
    "registered_class",
    "registered_names",
    "registered_robot_names",
    "robot_class",
    "source_of",
]

RobotModelMeta = RegisteringMeta
"""robosuite's name for the metaclass of robot classes."""


def register_robot(cls: type[RobotModel]) -> type[RobotModel]:
    """Register ``cls`` by its class name; usable as a decorator (it returns the class)."""
    return REGISTERED_ROBOTS.register(cls)


def register_base(cls: type[RobotBaseModel]) -> type[RobotBaseModel]:
    """Register a base class by its name; usable as a decorator."""
    return REGISTERED_BASES.register(cls)


def register_gripper(cls: type[GripperModel]) -> type[GripperModel]:
    """Register a gripper class by its name; usable as a decorator."""
    return REGISTERED_GRIPPERS.register(cls)


def registered_robot_names() -> list[str]:
    """The names of all registered robots, sorted."""
    return sorted(REGISTERED_ROBOTS)


def registered_names(family: str | None = None) -> list[str]:
    """The registered names of one family (robot, base, gripper), or of all of them, sorted."""
    tables = [REGISTRIES[family]] if family is not None else list(REGISTRIES.values())
    return sorted({name for table in tables for name in table})


def registered_class(family: str, name: str) -> Any:
    """The registered class ``name`` of ``family``; the error lists the names and the closest one."""
    return REGISTRIES[family].lookup(name)


def robot_class(name: str) -> type[RobotModel]:
    """The registered robot class called ``name``."""
    return REGISTERED_ROBOTS.lookup(name)


def find_registered(name: str) -> type[PartModel]:
    """The robot, base or gripper registered as ``name`` (robots first)."""
    for table in REGISTRIES.values():
        if name in table:
            return table[name]
    names = registered_names()
    raise RegistryError(
        f"unknown name '{name}'.{did_you_mean(name, names)} Registered: {summarize_names(names, limit=40)}"
    )
