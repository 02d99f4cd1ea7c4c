"""The registries: every concrete robot, base and gripper class by name, and the factories.

A metaclass registers each class as it is created, whether written in Python or made from a YAML
spec, in its family's table (robots, bases or grippers). A class that declares ``abstract = True``
in its own body (the morphology classes) is not registered; its subclasses are, unless they say
so themselves. Two different definitions of one name are an error that names both, instead of
robosuite's silent overwrite.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from assembler.errors import RegistryError, did_you_mean, summarize_names

if TYPE_CHECKING:
    from assembler.models.base_model import RobotBaseModel
    from assembler.models.gripper_model import GripperModel
    from assembler.models.robot_model import RobotModel
    from assembler.overrides import Overrides

REGISTERED_ROBOTS: dict[str, type[RobotModel]] = {}
"""Every registered robot class by name, in registration order."""

REGISTERED_BASES: dict[str, type[RobotBaseModel]] = {}
"""Every registered base class by name."""

REGISTERED_GRIPPERS: dict[str, type[GripperModel]] = {}
"""Every registered gripper class by name."""

_TABLES: dict[str, dict[str, Any]] = {
    "robot": REGISTERED_ROBOTS,
    "base": REGISTERED_BASES,
    "gripper": REGISTERED_GRIPPERS,
}


def source_of(cls: type) -> str:
    """Where a class was defined: its spec file position, or its Python module and name."""
    loaded = getattr(cls, "loaded", None)
    if loaded is not None:
        return str(loaded.source)
    return f"{cls.__module__}.{cls.__qualname__}"


def _register(cls: type, family: str) -> None:
    table = _TABLES[family]
    name = cls.__name__
    existing = table.get(name)
    if existing is not None and existing is not cls and source_of(existing) != source_of(cls):
        raise RegistryError(
            f"{family} '{name}' is defined twice: by {source_of(existing)} and by {source_of(cls)}; "
            "rename one of them"
        )
    table[name] = cls


class RegisteringMeta(type):
    """Registers every class it creates in its family's table, except those declaring ``abstract = True``."""

    def __new__(
        mcls, name: str, bases: tuple[type, ...], namespace: dict[str, Any], **kwargs: Any
    ) -> RegisteringMeta:
        cls = super().__new__(mcls, name, bases, namespace, **kwargs)
        if not namespace.get("abstract", False):
            _register(cls, cls.family)  # type: ignore[attr-defined]
        return cls


RobotModelMeta = RegisteringMeta
"""robosuite's name for the metaclass of robot classes."""


def register_robot(cls: type[RobotModel]) -> type[RobotModel]:
    """Register ``cls`` by its class name; usable as a decorator (it returns the class)."""
    _register(cls, "robot")
    return cls


def register_base(cls: type[RobotBaseModel]) -> type[RobotBaseModel]:
    """Register a base class by its name; usable as a decorator."""
    _register(cls, "base")
    return cls


def register_gripper(cls: type[GripperModel]) -> type[GripperModel]:
    """Register a gripper class by its name; usable as a decorator."""
    _register(cls, "gripper")
    return cls


def registered_robot_names() -> list[str]:
    """The names of all registered robots, sorted."""
    return sorted(REGISTERED_ROBOTS)


def registered_names() -> list[str]:
    """Every registered name of every family, sorted."""
    return sorted({name for table in _TABLES.values() for name in table})


def registered_class(family: str, name: str) -> Any:
    """The registered class ``name`` of ``family``; the error lists the names and the closest one."""
    table = _TABLES[family]
    try:
        return table[name]
    except KeyError:
        names = sorted(table)
        raise RegistryError(
            f"unknown {family} '{name}'.{did_you_mean(name, names)} "
            f"Registered {family}s: {summarize_names(names, limit=40)}"
        ) from None


def robot_class(name: str) -> type[RobotModel]:
    """The registered robot class called ``name``."""
    return registered_class("robot", name)  # type: ignore[no-any-return]


def create_robot(robot_name: str, *args: Any, overrides: Overrides = None, **kwargs: Any) -> RobotModel:
    """An instance of the registered robot ``robot_name``, e.g. ``create_robot("Sparrow7", idn=1)``.

    ``overrides`` (``{"joint_defaults.damping": 0.2}`` or ``["init_qpos[3]=-2.0"]``) change spec
    fields for this instance only; the registered class is left as it is."""
    cls = robot_class(robot_name)
    if overrides:
        from assembler.overrides import with_overrides  # the loader imports this module

        cls = with_overrides(cls, overrides)
    return cls(*args, **kwargs)


def create_base(base_name: str, idn: int | str = 0) -> RobotBaseModel:
    """An instance of the registered base ``base_name``."""
    return registered_class("base", base_name)(idn=idn)  # type: ignore[no-any-return]


def create_gripper(gripper_name: str, idn: int | str = 0) -> GripperModel:
    """An instance of the registered gripper ``gripper_name``; robots pass ``idn="{robot_idn}_{arm}"``."""
    return registered_class("gripper", gripper_name)(idn=idn)  # type: ignore[no-any-return]
