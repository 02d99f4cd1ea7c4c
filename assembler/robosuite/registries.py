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

import inspect
import logging
from collections.abc import Iterable, MutableMapping
from types import ModuleType
from typing import Any, TypeAlias

import robosuite.models.bases as robosuite_bases
import robosuite.models.grippers as robosuite_grippers
import robosuite.models.robots as robosuite_robots
import robosuite.robots as robosuite_robot_types
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.robots import ROBOT_CLASS_MAPPING

from assembler import models
from assembler.errors import Problem, RegistryError
from assembler.models.registering import REGISTRIES
from assembler.robosuite.controllers import CONFIGS
from assembler.robosuite.conventions import robot_type_name
from assembler.robosuite.part_classes import recorded_class, robosuite_class_of
from assembler.robosuite.registrations import Registration, SpecClassOf, family_of
from assembler.robosuite.robot_class import robosuite_robot, robot_class
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


Installable: TypeAlias = "type[models.PartModel] | Registration"  # a string: read by type checkers only
"""A spec class, or the registration record of a shipped spec not read yet."""


def _family_and_name(item: Installable) -> tuple[str, str]:
    if isinstance(item, Registration):
        return item.family, item.name
    return family_of(item), item.__name__


def _spec_class(item: Installable) -> type[models.PartModel]:
    """The spec class of ``item`` (a registration's is looked up: its spec read)."""
    if isinstance(item, Registration):
        return REGISTRIES[item.family].lookup(item.name)
    return item


def registered_class(family: str, name: str) -> type | None:
    """The class robosuite's table holds for ``name`` (robosuite keeps its null gripper under None)."""
    table = TABLES[family][0]
    return table.get(None) if family == "gripper" and name == NULL_GRIPPER else table.get(name)


def robosuite_has(family: str, name: str) -> bool:
    """Whether robosuite itself defines ``name``: its own class is registered under it, or the class of
    robosuite_models, the companion package robosuite imports itself when it is installed."""
    existing = registered_class(family, name)
    return existing is not None and existing.__module__.startswith(("robosuite.", "robosuite_models."))


def ours(existing: type | None) -> type[models.PartModel] | None:
    """The spec class behind a registered robosuite class of ours, or None (read, when it was
    installed from its registration record)."""
    return getattr(existing, "assembler_class", None)


def is_ours(existing: type | None) -> bool:
    """Whether ``existing`` is a robosuite class of ours, without reading its spec."""
    return inspect.getattr_static(existing, "assembler_class", None) is not None


def _registration(existing: type | None) -> Registration | None:
    """The registration record a class of ours was installed from, if it still stands for its spec."""
    found = inspect.getattr_static(existing, "registration", None)
    return found if isinstance(found, Registration) else None


def _same_spec(registered: type[models.PartModel] | None, spec_class: type[models.PartModel]) -> bool:
    """Whether ``registered`` is ``spec_class``, or the same spec registered again (a folder given both
    in ``ASSEMBLER_ROBOSUITE_SPECS`` and to ``register``): registering it again changes nothing."""
    return registered is spec_class or (registered is not None and registered.spec == spec_class.spec)


def _conflict(item: Installable, replace: bool, replace_ours: bool) -> Problem | None:
    """Why ``item`` cannot take its name in robosuite's table, if it cannot (a registration's spec is
    read only to compare it with another spec of ours, or to say where the name is)."""
    family, name = _family_and_name(item)
    existing = registered_class(family, name)
    if existing is None or (isinstance(item, Registration) and _registration(existing) == item):
        return None
    if replace_ours and is_ours(existing):
        return None
    if is_ours(existing) and _same_spec(ours(existing), _spec_class(item)):
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
    return _spec_class(item).spec_problem(NAME, message)


def _robosuite_class(item: Installable) -> type:
    """robosuite's class for ``item``: a registration's stands for its spec class until it is used."""
    if not isinstance(item, Registration):
        return robot_class(item) if issubclass(item, models.ManipulatorModel) else robosuite_class_of(item)
    stand_in = SpecClassOf(item.family, item.name)
    if item.family == "robot":
        made = robosuite_robot(item.name, item.arms, stand_in)
    else:
        made = recorded_class(item.family, item.name, item.base_type, stand_in)
    made.registration = item  # what _conflict compares
    return made


def install(
    spec_classes: Iterable[Installable], replace: bool = False, replace_ours: bool = False
) -> list[str]:
    """Put the robosuite class of each spec class (or registration record) in robosuite's tables
    (all, or none on a conflict); ``replace`` lets a spec take a name robosuite uses itself,
    ``replace_ours`` one a spec of ours has (an experiment's variant of it). Returns the names
    installed."""
    items = list(spec_classes)
    problems = [problem for item in items if (problem := _conflict(item, replace, replace_ours))]
    if problems:
        raise RegistryError(problems)
    made = [(item, _robosuite_class(item)) for item in items]
    names = [_family_and_name(item) for item in items]
    replacing = [name for family, name in names if robosuite_has(family, name)]
    for item, robosuite_cls in made:
        _write(item, robosuite_cls)
    if replacing:
        _replaced.extend(name for name in replacing if name not in _replaced)
        LOG.info("robosuite's %s replaced by the specs of the same names", ", ".join(replacing))
    return [name for _, name in names]


def _write(item: Installable, robosuite_cls: type) -> None:
    family, name = _family_and_name(item)
    table, module = TABLES[family]
    robosuites_own = robosuite_has(family, name)
    if family == "gripper" and name == NULL_GRIPPER:
        table[None] = robosuite_cls  # robosuite knows its null gripper by None only
    else:
        table[name] = robosuite_cls
    if robosuites_own:
        setattr(module, name, robosuite_cls)  # robosuite's tests import classes by module attribute
    if family == "robot":
        if robosuites_own:
            CONFIGS.robosuites_own.add(name)
        else:
            robot_type = item.robot_type if isinstance(item, Registration) else robot_type_name(item)  # type: ignore[arg-type]
            # robosuite's names keep theirs
            ROBOT_CLASS_MAPPING.setdefault(name, getattr(robosuite_robot_types, robot_type))
        CONFIGS.robots[name] = robosuite_cls


def replaced() -> list[str]:
    """robosuite's own robots, grippers and bases replaced by specs in this process."""
    return list(_replaced)


def installed(family: str) -> list[str]:
    """The names of ``family`` (robot, gripper or base) whose robosuite class is one of ours."""
    return sorted(cls.__name__ for cls in TABLES[family][0].values() if is_ours(cls))
