"""Specs -> classes: the shipped specs at import, user folders with one call, overridden variants.

Each validated spec becomes a real class, ``type(spec.name, (TypeClass,), {...})``, and the
registry's metaclass registers it on creation, exactly like a hand-written subclass. A batch of
specs registers all or nothing, across robots, bases and grippers.
"""

from __future__ import annotations

import contextlib
from collections.abc import Iterable, Iterator, Sequence
from pathlib import Path
from typing import Any, TypeVar

import yaml

from assembler.errors import AssemblerError, Problem, RegistryError
from assembler.files.paths import is_file, shipped_specs_dir
from assembler.models import (
    BASE_TYPE_CLASSES,
    MORPHOLOGY_CLASSES,
    REGISTRIES,
    GripperModel,
    PartModel,
    source_of,
)
from assembler.models.motor_table import MOTORS
from assembler.registry import shipped
from assembler.registry.same_spec import same_spec, shipped_note
from assembler.spec.documents import (
    LoadedSpec,
    LocatedDocument,
    Override,
    Overrides,
    blame,
    overridden_spec,
    parse_overrides,
)
from assembler.spec.documents import apply_overrides as apply_document_overrides
from assembler.spec.fieldpath import FieldPath
from assembler.spec.part_arguments import SPEC_SUFFIXES, ArgumentKind, argument_kind
from assembler.spec.schema import SPEC_KINDS, BaseSpec, MotorSpec, PartSpec, RobotSpec
from assembler.spec.spec_files import MOTOR_KIND, load_spec_paths, load_string

NAME = FieldPath(("name",))
P = TypeVar("P", bound=PartModel)


def kind_of(spec: PartSpec) -> str:
    """robot, base or gripper."""
    return str(getattr(spec, "kind", "robot"))


class RegistryParents:
    """``extends: <name>`` looks in the registry: the merged documents of spec-made classes."""

    def document(self, name: str) -> LocatedDocument | None:
        for table in REGISTRIES.values():
            loaded = getattr(table.get(name), "loaded", None)
            if loaded is not None:
                return loaded.document  # type: ignore[no-any-return]
        return None

    def names(self, kind: str) -> list[str]:
        return sorted(REGISTRIES[kind]) if kind in REGISTRIES else []


PARENTS = RegistryParents()


def parent_class(spec: PartSpec) -> type[PartModel]:
    """The class a spec's class derives from: its morphology, base type or the gripper class."""
    if isinstance(spec, RobotSpec):
        return MORPHOLOGY_CLASSES[spec.morphology]
    if isinstance(spec, BaseSpec):
        return BASE_TYPE_CLASSES[spec.type]
    return GripperModel


def class_from_spec(loaded: LoadedSpec[Any], register: bool = True) -> type[PartModel]:
    """Create the class a spec describes; it registers itself unless ``register`` is False (e.g. the
    two versions of one spec that ``assembler diff`` compares)."""
    spec = loaded.spec
    namespace = {
        "in_registry": register,
        "spec": spec,
        "loaded": loaded,
        "__doc__": spec.description or f"{kind_of(spec).title()} '{spec.name}' from {loaded.source}.",
        "__module__": __name__,  # a module that exists: the one that made the class
    }
    return type(spec.name, (parent_class(spec),), namespace)


def _check_names(batch: list[LoadedSpec[PartSpec]]) -> None:
    """No name twice in the batch, and none already registered by another spec of its family."""
    problems: list[Problem] = []
    first: dict[tuple[str, str], LoadedSpec[PartSpec]] = {}
    for loaded in batch:
        name, kind = loaded.spec.name, kind_of(loaded.spec)
        earlier = first.setdefault((kind, name), loaded)
        if earlier is not loaded and earlier.source != loaded.source:
            problems.append(
                loaded.problem(NAME, f"{kind} '{name}' is also defined by {earlier.source}; rename one")
            )
        existing = REGISTRIES[kind].get(name)
        if existing is not None and source_of(existing) != loaded.source and not same_spec(existing, loaded):
            where = f"{source_of(existing)}{shipped_note(existing)}"
            message = f"{kind} '{name}' is already registered by {where}, a different spec; rename one"
            problems.append(loaded.problem(NAME, message))
    if problems:
        raise RegistryError(problems)


@contextlib.contextmanager
def _all_or_nothing() -> Iterator[None]:
    with contextlib.ExitStack() as stack:
        for table in REGISTRIES.values():
            stack.enter_context(table.transaction())
        yield


def register_loaded(
    batch: list[LoadedSpec[PartSpec]], motors: Sequence[LoadedSpec[MotorSpec]] = ()
) -> list[type[PartModel]]:
    """Register a batch of validated specs (and the motor specs beside them): all of them, or (on any
    problem) none."""
    _check_names(batch)
    with _all_or_nothing(), MOTORS.transaction():
        MOTORS.add(motors)
        for loaded in batch:  # the same spec as a registered copy (checked above): the file given wins
            table = REGISTRIES[kind_of(loaded.spec)]
            existing = table.get(loaded.spec.name)
            if existing is not None and source_of(existing) != loaded.source:
                del table[loaded.spec.name]
        return [class_from_spec(loaded) for loaded in batch]


def register_specs(*paths: str | Path) -> list[type[PartModel]]:
    """Validate and register every spec in the given files and folders (all or nothing), motor specs
    among them."""
    return register_loaded(*load_spec_paths(paths, PARENTS))


def register_spec_string(text: str) -> type[PartModel]:
    """Validate and register one spec written as YAML text."""
    (cls,) = register_loaded([load_string(text, PARENTS)])
    return cls


def load_shipped_specs() -> list[type[PartModel]]:
    """Read every spec this project ships now (each is otherwise read when its name is first looked
    up: :mod:`assembler.registry.shipped`); returns their classes."""
    folder = shipped_specs_dir().resolve()
    return [
        cls
        for table in REGISTRIES.values()  # a whole read: makes every held name
        for cls in table.values()
        if cls.loaded is not None
        and cls.loaded.document.path is not None
        and cls.loaded.document.path.is_relative_to(folder)
    ]


def add_spec_folders(folders: Iterable[str | Path]) -> list[type[PartModel]]:
    """Register the user's spec folders (the CLI's ``--specs`` flag)."""
    folders = list(folders)
    return register_specs(*folders) if folders else []


def _part_specs_beside(files: Sequence[Path]) -> list[Path]:
    """The part spec files in the folders of ``files``, not recursively, ``files`` left out (scene
    and experiment files are not parts: their commands read them)."""
    given = {file.resolve() for file in files}
    beside = []
    for folder in dict.fromkeys(file.resolve().parent for file in files):
        for path in sorted(folder.iterdir()):
            if not path.name.endswith(SPEC_SUFFIXES) or path.resolve() in given or not path.is_file():
                continue
            try:
                data = yaml.safe_load(path.read_text(encoding="utf-8"))
            except (OSError, UnicodeDecodeError, yaml.YAMLError):
                continue  # not ours to report: the file was not asked for
            if isinstance(data, dict) and data.get("kind", "robot") in (*SPEC_KINDS, MOTOR_KIND):
                beside.append(path)
    return beside


def register_with_siblings(paths: Sequence[str | Path]) -> list[type[PartModel]]:
    """Register spec files and folders together with the part specs beside each file, which it may
    name (``specs/z1_with_gripper.yaml`` naming the gripper of ``specs/z1_gripper.yaml``); return the
    classes of ``paths`` only. A spec beside it that does not load never blocks it: the paths are
    then registered alone, and report their own problems."""
    files = [Path(path) for path in paths if is_file(path)]  # a name too long is no file: said later
    siblings = _part_specs_beside(files)
    if not siblings:
        return register_specs(*paths)
    try:
        classes = register_specs(*paths, *siblings)
    except AssemblerError:
        return register_specs(*paths)
    beside = {path.resolve() for path in siblings}
    return [cls for cls in classes if cls.loaded is None or cls.loaded.document.path not in beside]


def classes_named(references: Sequence[str]) -> list[type[PartModel]]:
    """The parts ``references`` name: spec files and folders (registered together, with the specs
    beside each file, so they may extend and name each other), then registered robot, base or
    gripper names."""
    paths = [r for r in references if argument_kind(r) is not ArgumentKind.NAME]
    classes = register_with_siblings(paths) if paths else []
    for name in (r for r in references if r not in paths):
        for table in REGISTRIES.values():
            if name in table:
                classes.append(table[name])
                break
        else:
            classes.append(REGISTRIES["robot"].lookup(name))  # "unknown robot ... Did you mean"
    return classes


# ----- overrides: a variant of a class, never registered ---------------------------------------


def loaded_of(cls: type[PartModel]) -> LoadedSpec[Any]:
    """The spec document of a class (a class written in Python: its spec as a document)."""
    if cls.loaded is not None:
        return cls.loaded
    data = cls.spec.model_dump(mode="json")
    return LoadedSpec(spec=cls.spec, document=LocatedDocument(data, f"<class {cls.__qualname__}>"))


def check_override_paths(cls: type[PartModel], overrides: list[Override]) -> None:
    """Raise :class:`SpecError` if a path does not exist in ``cls``'s spec; values are not checked."""
    loaded = loaded_of(cls)
    apply_document_overrides(loaded.document, type(loaded.spec), overrides)


def applied_overrides(cls: type) -> tuple[Override, ...]:
    """The overrides a class was made with (none for a registered class)."""
    return tuple(getattr(cls, "applied_overrides", ()))


def with_overrides(cls: type[P], overrides: Overrides, label: str = "override ") -> type[P]:
    """``cls`` itself when there is nothing to override, else an unregistered subclass of the
    same name whose ``spec`` has the overrides applied."""
    items = parse_overrides(overrides, label)
    if not items:
        return cls
    loaded = overridden_spec(loaded_of(cls), items)

    def prepared(self: P) -> Any:
        # Checks against the MJCF (joint counts, names, files) name the override, not the spec.
        try:
            return cls.prepared(self)
        except AssemblerError as error:
            raise type(error)([blame(p, items, note=False) for p in error.problems]) from None

    namespace = {
        "prepared": prepared,
        "in_registry": False,  # the reviewed spec stays registered
        "spec": loaded.spec,
        "loaded": loaded,
        "applied_overrides": (*applied_overrides(cls), *items),
        "__doc__": cls.__doc__,
        "__module__": cls.__module__,
        "__qualname__": cls.__qualname__,
    }
    return type(cls.__name__, (cls,), namespace)


shipped.hold_shipped_names()  # the registries always hold the shipped names once the catalog is in use
