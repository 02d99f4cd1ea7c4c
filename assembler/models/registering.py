"""The registries: every concrete robot, base and gripper class by name, filled as classes are made.

A metaclass registers each class as it is created, whether written in Python or made from a YAML
spec, in its family's :class:`Registry` (the class attribute ``registry``). A class that says
``in_registry = False`` in its own body (the morphology and base-type classes, a diff's two
versions of one spec, an overridden spec) is not registered; its subclasses are, unless they say
so themselves. Two different definitions of one name are an error that names both, instead of
robosuite's silent overwrite.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import Any, ClassVar, Generic, TypeVar

from assembler.errors import RegistryError, did_you_mean, summarize_names

T = TypeVar("T")


def source_of(cls: type) -> str:
    """Where a class was defined: its spec file position, or its Python module and name."""
    loaded = getattr(cls, "loaded", None)
    if loaded is not None:
        return str(loaded.source)
    return f"{cls.__module__}.{cls.__qualname__}"


def unknown_name(family: str, name: str, known: list[str]) -> str:
    """The one wording of an unknown name: the closest known name if there is one, else all of them."""
    suggestion = did_you_mean(name, known)
    if suggestion:
        return f"unknown {family} '{name}'.{suggestion}"
    return (
        f"unknown {family} '{name}'. Registered {family}s: {summarize_names(known, limit=40)}; a spec in "
        "another folder is found with --specs FOLDER (assembler.register_specs in Python)"
    )


class Registry(dict[str, type[T]], Generic[T]):
    """One family's classes by name (robot, base or gripper), in registration order."""

    def __init__(self, family: str) -> None:
        super().__init__()
        self.family = family

    def register(self, cls: type[T]) -> type[T]:
        """Add ``cls`` under its class name; a different class of the same name is an error."""
        name = cls.__name__
        existing = self.get(name)
        if existing is not None and existing is not cls and source_of(existing) != source_of(cls):
            raise RegistryError(
                f"{self.family} '{name}' is defined twice: by {source_of(existing)} and by {source_of(cls)}; "
                "rename one of them"
            )
        self[name] = cls
        return cls

    def lookup(self, name: str) -> type[T]:
        """The class registered as ``name``; the error lists the names and the closest one."""
        try:
            return self[name]
        except KeyError:
            raise RegistryError(unknown_name(self.family, name, sorted(self))) from None

    @contextlib.contextmanager
    def transaction(self) -> Iterator[None]:
        """Registrations in the block are undone if the block fails."""
        before = dict(self)
        try:
            yield
        except BaseException:
            self.clear()
            self.update(before)
            raise


class RegisteringMeta(type):
    """Registers every class it creates in the class's ``registry``, unless its body says
    ``in_registry = False``."""

    registry: ClassVar[Registry[Any]]

    def __new__(
        mcls, name: str, bases: tuple[type, ...], namespace: dict[str, Any], **kwargs: Any
    ) -> RegisteringMeta:
        cls = super().__new__(mcls, name, bases, namespace, **kwargs)
        if namespace.get("in_registry", True):
            cls.registry.register(cls)
        return cls
