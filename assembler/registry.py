"""The robot registry: every concrete robot class, by name, and ``create_robot`` to build one.

A metaclass registers each class as it is created, whether written in Python or made from a YAML
spec. A class that declares ``abstract = True`` in its own body (the morphology classes) is not
registered; its subclasses are, unless they say so themselves. Two different definitions of one
name are an error that names both, instead of robosuite's silent overwrite.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Any

from assembler.errors import RegistryError, did_you_mean, summarize_names

if TYPE_CHECKING:
    from assembler.models.robot_model import RobotModel

REGISTERED_ROBOTS: dict[str, type[RobotModel]] = {}
"""Every registered robot class by name, in registration order."""


def source_of(cls: type) -> str:
    """Where a class was defined: its spec file position, or its Python module and name."""
    loaded = getattr(cls, "loaded", None)
    if loaded is not None:
        return str(loaded.source)
    return f"{cls.__module__}.{cls.__qualname__}"


def _register(cls: type[RobotModel]) -> None:
    name = cls.__name__
    existing = REGISTERED_ROBOTS.get(name)
    if existing is not None and existing is not cls and source_of(existing) != source_of(cls):
        raise RegistryError(
            f"robot '{name}' is defined twice: by {source_of(existing)} and by {source_of(cls)}; "
            "rename one of them"
        )
    REGISTERED_ROBOTS[name] = cls


class RobotModelMeta(type):
    """Registers every robot class it creates, except those declaring ``abstract = True``."""

    def __new__(
        mcls, name: str, bases: tuple[type, ...], namespace: dict[str, Any], **kwargs: Any
    ) -> RobotModelMeta:
        cls = super().__new__(mcls, name, bases, namespace, **kwargs)
        if not namespace.get("abstract", False):
            _register(cls)  # type: ignore[arg-type]
        return cls


def register_robot(cls: type[RobotModel]) -> type[RobotModel]:
    """Register ``cls`` by its class name; usable as a decorator (it returns the class)."""
    _register(cls)
    return cls


def registered_robot_names() -> list[str]:
    """The names of all registered robots, sorted."""
    return sorted(REGISTERED_ROBOTS)


def robot_class(name: str) -> type[RobotModel]:
    """The registered class called ``name``; the error lists the names and the closest one."""
    try:
        return REGISTERED_ROBOTS[name]
    except KeyError:
        names = registered_robot_names()
        raise RegistryError(
            f"unknown robot '{name}'.{did_you_mean(name, names)} "
            f"Registered robots: {summarize_names(names, limit=40)}"
        ) from None


def create_robot(robot_name: str, *args: Any, **kwargs: Any) -> RobotModel:
    """An instance of the registered robot ``robot_name``, e.g. ``create_robot("Sparrow7", idn=1)``."""
    return robot_class(robot_name)(*args, **kwargs)
