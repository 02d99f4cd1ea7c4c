"""Our spec classes in robosuite's registries, with no name ever meaning two things in silence.

robosuite finds robots, grippers and bases by name in four tables (``REGISTERED_ROBOTS``,
``ROBOT_CLASS_MAPPING``, ``GRIPPER_MAPPING``, ``BASE_MAPPING``) and its tests also by module
attribute (``robosuite.models.grippers.PandaGripper``). A spec whose name robosuite already uses
(our specs of robosuite's own robots, or a user's "Panda") enters only when replacement is asked
for; otherwise registering it is an error that names both. Replacements are logged in one line and
listed by :func:`replaced`. Robots of robosuite's names keep robosuite's Robot class (GR1 is a
LeggedRobot); new names get theirs from :mod:`assembler.robosuite.conventions`.
"""

from __future__ import annotations

import logging
from collections.abc import Iterable, MutableMapping
from types import ModuleType
from typing import Any

import robosuite.models.bases as robosuite_bases
import robosuite.models.grippers as robosuite_grippers
import robosuite.models.robots as robosuite_robots
import robosuite.robots as robosuite_robot_types
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.robots import ROBOT_CLASS_MAPPING

from assembler.errors import Problem, RegistryError
from assembler.models import GripperModel, ManipulatorModel, PartModel, RobotBaseModel
from assembler.robosuite.controllers import CONFIGS
from assembler.robosuite.conventions import robot_type_name
from assembler.robosuite.part_classes import robosuite_class_of
from assembler.robosuite.robot_class import robot_class
from assembler.spec.fieldpath import FieldPath

LOG = logging.getLogger("assembler.robosuite")
NAME = FieldPath(("name",))

TABLES: dict[str, tuple[MutableMapping[Any, type], ModuleType]] = {
    "robot": (REGISTERED_ROBOTS, robosuite_robots),
    "gripper": (robosuite_grippers.GRIPPER_MAPPING, robosuite_grippers),
    "base": (robosuite_bases.BASE_MAPPING, robosuite_bases),
}
"""Per family, robosuite's table of classes by name and the module its tests import them from."""

NULL_GRIPPER = "NullGripper"
"""robosuite's gripper for "no gripper": ``GRIPPER_MAPPING[None]``."""

_replaced: list[str] = []


def family_of(spec_class: type[PartModel]) -> str:
    """robot, gripper or base."""
    if issubclass(spec_class, ManipulatorModel):
        return "robot"
    if issubclass(spec_class, GripperModel):
        return "gripper"
    if issubclass(spec_class, RobotBaseModel):
        return "base"
    raise RegistryError(f"{spec_class.__name__}: robosuite takes robots with arms, grippers and bases only")


def registered_class(family: str, name: str) -> type | None:
    """The class robosuite's table holds for ``name`` (robosuite keeps its null gripper under None)."""
    table = TABLES[family][0]
    return table.get(None) if family == "gripper" and name == NULL_GRIPPER else table.get(name)


def robosuite_has(family: str, name: str) -> bool:
    """Whether robosuite itself defines ``name``: its own class is registered under it, or the class of
    robosuite_models, the companion package robosuite imports itself when it is installed."""
    existing = registered_class(family, name)
    return existing is not None and existing.__module__.startswith(("robosuite.", "robosuite_models."))


def ours(existing: type | None) -> type[PartModel] | None:
    """The spec class behind a registered robosuite class of ours, or None."""
    return getattr(existing, "assembler_class", None)


def _same_spec(registered: type[PartModel] | None, spec_class: type[PartModel]) -> bool:
    """Whether ``registered`` is ``spec_class``, or the same spec registered again (a folder given both
    in ``ASSEMBLER_ROBOSUITE_SPECS`` and to ``register``): registering it again changes nothing."""
    return registered is spec_class or (registered is not None and registered.spec == spec_class.spec)


def _conflict(spec_class: type[PartModel], replace: bool, replace_ours: bool) -> Problem | None:
    """Why ``spec_class`` cannot take its name in robosuite's table, if it cannot."""
    family, name = family_of(spec_class), spec_class.__name__
    existing = registered_class(family, name)
    if existing is None or _same_spec(ours(existing), spec_class):
        return None
    if replace_ours and ours(existing) is not None:
        return None
    if robosuite_has(family, name):
        if replace:
            return None
        message = (
            f"robosuite has its own {family} '{name}': rename the spec, or replace robosuite's with it "
            f"(assembler.robosuite.register(..., replace_robosuite=True))"
        )
    else:
        where = ours(existing) or existing
        owner = f"{where.__module__}.{where.__qualname__}"
        message = f"robosuite's {family} '{name}' is already {owner}; rename the spec"
    return spec_class.spec_problem(NAME, message)


def install(
    spec_classes: Iterable[type[PartModel]], replace: bool = False, replace_ours: bool = False
) -> list[str]:
    """Put the robosuite class of each spec class in robosuite's tables (all, or none on a conflict);
    ``replace`` lets a spec take a name robosuite uses itself, ``replace_ours`` one a spec of ours has
    (an experiment's variant of it). Returns the names installed."""
    classes = list(spec_classes)
    problems = [problem for cls in classes if (problem := _conflict(cls, replace, replace_ours))]
    if problems:
        raise RegistryError(problems)
    made = [
        (cls, robot_class(cls) if issubclass(cls, ManipulatorModel) else robosuite_class_of(cls))
        for cls in classes
    ]
    replacing = [cls.__name__ for cls in classes if robosuite_has(family_of(cls), cls.__name__)]
    for cls, robosuite_cls in made:
        _write(cls, robosuite_cls)
    if replacing:
        _replaced.extend(name for name in replacing if name not in _replaced)
        LOG.info("robosuite's %s replaced by the specs of the same names", ", ".join(replacing))
    return [cls.__name__ for cls in classes]


def _write(spec_class: type[PartModel], robosuite_cls: type) -> None:
    family, name = family_of(spec_class), spec_class.__name__
    table, module = TABLES[family]
    robosuites_own = robosuite_has(family, name)
    if family == "gripper" and name == NULL_GRIPPER:
        table[None] = robosuite_cls  # robosuite knows its null gripper by None only
    else:
        table[name] = robosuite_cls
    if robosuites_own:
        setattr(module, name, robosuite_cls)  # robosuite's tests import classes by module attribute
    if issubclass(spec_class, ManipulatorModel):
        if robosuites_own:
            CONFIGS.robosuites_own.add(name)
        else:
            ROBOT_CLASS_MAPPING.setdefault(
                name, getattr(robosuite_robot_types, robot_type_name(spec_class))
            )  # robosuite's names keep theirs
        CONFIGS.robots[name] = spec_class


def replaced() -> list[str]:
    """robosuite's own robots, grippers and bases replaced by specs in this process."""
    return list(_replaced)


def installed(family: str) -> list[str]:
    """The names of ``family`` (robot, gripper or base) whose robosuite class is one of ours."""
    return sorted(cls.__name__ for cls in TABLES[family][0].values() if ours(cls) is not None)
