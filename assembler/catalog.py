"""Specs -> registered classes: the shipped specs at import, user folders with one call.

Each validated spec becomes a real class, ``type(spec.name, (MorphologyClass,), {...})``, and the
registry's metaclass registers it on creation, exactly like a hand-written subclass.
"""

from __future__ import annotations

from collections.abc import Iterable
from pathlib import Path
from typing import Any

from assembler.errors import Problem, RegistryError
from assembler.loader import LoadedSpec, load_paths, load_string
from assembler.models import KIND_CLASSES, MORPHOLOGY_CLASSES, PartModel
from assembler.paths import shipped_specs_dir
from assembler.registry import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS, source_of
from assembler.schema import RobotSpec
from assembler.yaml_source import LocatedDocument

TABLES: dict[str, dict[str, Any]] = {
    "robot": REGISTERED_ROBOTS,
    "base": REGISTERED_BASES,
    "gripper": REGISTERED_GRIPPERS,
}


def kind_of(loaded: LoadedSpec) -> str:
    """robot, base or gripper."""
    return str(getattr(loaded.spec, "kind", "robot"))


def registered_document(name: str) -> LocatedDocument | None:
    """The merged spec document of a registered spec-made part, for ``extends: <name>``."""
    for table in TABLES.values():
        loaded = getattr(table.get(name), "loaded", None)
        if loaded is not None:
            return loaded.document  # type: ignore[no-any-return]
    return None


def class_from_spec(loaded: LoadedSpec, register: bool = True) -> type[PartModel]:
    """Create the class a spec describes; it registers itself unless ``register`` is False (e.g. the
    two versions of one spec that ``assembler diff`` compares)."""
    spec = loaded.spec
    parent = (
        MORPHOLOGY_CLASSES[spec.morphology] if isinstance(spec, RobotSpec) else KIND_CLASSES[kind_of(loaded)]
    )
    namespace = {
        "abstract": not register,  # the registry's metaclass skips abstract classes
        "spec": spec,
        "loaded": loaded,
        "__doc__": spec.description or f"{kind_of(loaded).title()} '{spec.name}' from {loaded.source}.",
        "__module__": "assembler.specs",
    }
    return type(spec.name, (parent,), namespace)


def _check_names(batch: list[LoadedSpec]) -> None:
    problems: list[Problem] = []
    first: dict[str, LoadedSpec] = {}
    for loaded in batch:
        name = loaded.spec.name
        where = loaded.location(("name",))
        if name in first and first[name].source != loaded.source:
            problems.append(
                Problem(
                    f"robot '{name}' is also defined by {first[name].source}; rename one",
                    where,
                    "name",
                )
            )
        first.setdefault(name, loaded)
        existing = REGISTERED_ROBOTS.get(name)
        if existing is not None and source_of(existing) != loaded.source:
            problems.append(
                Problem(
                    f"robot '{name}' is already registered by {source_of(existing)}; rename one",
                    where,
                    "name",
                )
            )
    if problems:
        raise RegistryError(problems)


def register_specs(*paths: str | Path) -> list[type[PartModel]]:
    """Validate and register every spec in the given files and folders (all or nothing)."""
    batch = load_paths(paths, registered_document)
    _check_names(batch)
    return [class_from_spec(loaded) for loaded in batch]


def register_spec_string(text: str) -> type[PartModel]:
    """Validate and register one spec written as YAML text."""
    loaded = load_string(text, registered_document)
    _check_names([loaded])
    return class_from_spec(loaded)


def load_shipped_specs() -> list[type[PartModel]]:
    """Register the specs this project ships; called once when ``assembler`` is imported."""
    folder = shipped_specs_dir()
    return register_specs(folder) if folder.is_dir() else []


def add_spec_folders(folders: Iterable[str | Path]) -> list[type[PartModel]]:
    """Register the user's spec folders (the CLI's ``--specs`` flag)."""
    folders = list(folders)
    return register_specs(*folders) if folders else []
