"""The registries: every concrete robot, base and gripper class by name, filled as classes are made.

A metaclass registers each class as it is created, whether written in Python or made from a YAML
spec, in its family's :class:`Registry` (the class attribute ``registry``). A class that says
``in_registry = False`` in its own body (the morphology and base-type classes, a diff's two
versions of one spec, an overridden spec) is not registered; its subclasses are, unless they say
so themselves. Two different definitions of one name are an error that names both, instead of
robosuite's silent overwrite.

A registry may hold names whose classes are not made yet (:class:`Unmade`: the shipped specs, each
read when its name is first looked up; :mod:`assembler.registry.shipped`). Looking a name up makes
its class; anything that reads the whole table (iterating, ``len``, ``keys``, ``values``,
``items``, ``dict(table)``), or writes a held name directly (``table[name] = cls``, ``del``),
makes them all first, so a registry always answers as the complete table it stands for.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterator
from typing import TYPE_CHECKING, Any, ClassVar, Generic, Protocol, TypeVar, overload

from assembler.errors import RegistryError, did_you_mean, summarize_names

if TYPE_CHECKING:  # the view types of dict's keys(), values() and items()
    from _collections_abc import dict_items, dict_keys, dict_values

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


class Unmade(Protocol):
    """Names registered before their classes are made, and how to make them."""

    def holds(self, family: str, name: str) -> bool:
        """Whether ``name`` of ``family`` is registered but its class not made yet."""

    def make(self, family: str, name: str) -> None:
        """Make and register the class of ``name``, once: a lookup of it meanwhile waits for it."""

    def make_all(self) -> None:
        """Make and register every class still held, of every family."""

    def held(self, family: str) -> list[str]:
        """The names of ``family`` registered but not made yet."""

    def state(self) -> object:
        """What :meth:`restore` needs to undo the makes that follow."""

    def restore(self, state: object) -> None:
        """Hold again what was held at ``state`` (the makes of a failed registration are undone)."""


class Registry(dict[str, type[T]], Generic[T]):
    """One family's classes by name (robot, base or gripper), in registration order."""

    def __init__(self, family: str) -> None:
        super().__init__()
        self.family = family
        self.unmade: Unmade | None = None
        """The names this table holds without their classes (see the module), if any."""

    # ----- a name looked up makes its class; a whole read makes them all ----------------------

    def _made(self, name: object) -> None:
        if self.unmade is not None and isinstance(name, str) and self.unmade.holds(self.family, name):
            self.unmade.make(self.family, name)

    def _all_made(self) -> None:
        if self.unmade is not None:
            self.unmade.make_all()

    def __getitem__(self, name: str) -> type[T]:
        self._made(name)
        return super().__getitem__(name)

    def __contains__(self, name: object) -> bool:
        self._made(name)
        return super().__contains__(name)

    @overload
    def get(self, name: str, default: None = None, /) -> type[T] | None: ...
    @overload
    def get(self, name: str, default: type[T] | Any, /) -> type[T] | Any: ...
    def get(self, name: str, default: Any = None, /) -> Any:
        self._made(name)
        return super().get(name, default)

    def _before_writing(self, name: object) -> None:
        # Writing a held name directly (robosuite's way, not register()) first makes every held
        # name, as when all were made at import: a shipped spec that extends the name written
        # over still extends the shipped one, and the name is not made again later.
        if self.unmade is not None and isinstance(name, str) and self.unmade.holds(self.family, name):
            self.unmade.make_all()

    def __setitem__(self, name: str, cls: type[T]) -> None:
        self._before_writing(name)
        super().__setitem__(name, cls)

    def __delitem__(self, name: str) -> None:
        self._before_writing(name)
        super().__delitem__(name)

    def pop(self, name: str, *default: Any) -> Any:
        self._before_writing(name)
        return super().pop(name, *default)

    def __iter__(self) -> Iterator[str]:
        self._all_made()
        return super().__iter__()

    def __reversed__(self) -> Iterator[str]:
        self._all_made()
        return super().__reversed__()

    def __len__(self) -> int:
        self._all_made()
        return super().__len__()

    def keys(self) -> dict_keys[str, type[T]]:
        self._all_made()
        return super().keys()

    def values(self) -> dict_values[str, type[T]]:
        self._all_made()
        return super().values()

    def items(self) -> dict_items[str, type[T]]:
        self._all_made()
        return super().items()

    def copy(self) -> dict[str, type[T]]:
        self._all_made()
        return dict(super().items())

    def __eq__(self, other: object) -> bool:
        self._all_made()
        return super().__eq__(other)

    def __repr__(self) -> str:
        self._all_made()
        return super().__repr__()

    def made(self) -> list[type[T]]:
        """The classes made so far, without making the held ones (whose files are known)."""
        return list(super().values())

    def held_names(self) -> list[str]:
        """The names registered without their classes yet, without making them (a lookup of one
        makes it)."""
        return self.unmade.held(self.family) if self.unmade is not None else []

    # ----- registering -------------------------------------------------------------------------

    def register(self, cls: type[T]) -> type[T]:
        """Add ``cls`` under its class name; a different class of the same name is an error."""
        name = cls.__name__
        existing = self.get(name)  # a held name is made first: two definitions are still an error
        if existing is not None and existing is not cls and source_of(existing) != source_of(cls):
            raise RegistryError(
                f"{self.family} '{name}' is defined twice: by {source_of(existing)} and by {source_of(cls)}; "
                "rename one of them"
            )
        super().__setitem__(name, cls)  # checked above: not a direct write
        return cls

    def lookup(self, name: str) -> type[T]:
        """The class registered as ``name``; the error lists the names and the closest one."""
        try:
            return self[name]
        except KeyError:
            raise RegistryError(unknown_name(self.family, name, sorted(self))) from None

    @contextlib.contextmanager
    def transaction(self) -> Iterator[None]:
        """Registrations in the block are undone if the block fails (and names made in it are held
        again)."""
        before = dict(super().items())  # what is made: the held names stay held
        held = self.unmade.state() if self.unmade is not None else None
        try:
            yield
        except BaseException:
            self.clear()
            self.update(before)
            if self.unmade is not None:
                self.unmade.restore(held)
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


REGISTRIES: dict[str, Registry[Any]] = {family: Registry(family) for family in ("robot", "base", "gripper")}
"""Each family's registry. They live here, apart from the classes they hold, so that reading them
(robosuite's bridge does, at every import) imports no model class and no schema: each family's
class module names its own table (``REGISTERED_ROBOTS``...)."""
