"""Part spec files and folders (robots, bases, grippers) -> validated specs, all problems at once.

A whole folder is loaded together, so specs in it may extend one another in any file order, and
every problem of every file is reported in one error. The document layer
(:mod:`assembler.spec.documents`) does the reading, inheritance and validation; this module picks each
document's model by its ``kind`` and walks folders.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from dataclasses import dataclass, field
from pathlib import Path

from assembler.errors import AssemblerError, Problem, SpecError
from assembler.files.paths import confine, display_path, is_dir
from assembler.spec.documents import (
    LoadedSpec,
    LocatedDocument,
    NoParents,
    Parents,
    Resolver,
    parse_yaml,
    read_document,
    resolve_path_fields,
    validate,
)
from assembler.spec.fieldpath import FieldPath
from assembler.spec.part_arguments import spec_files
from assembler.spec.schema import SPEC_KINDS, MotorSpec, PartSpec

__all__ = [
    "LoadedSpec",
    "load_documents",
    "load_motors",
    "load_paths",
    "load_spec_paths",
    "load_string",
    "spec_files",
]

KIND = FieldPath(("kind",))


def _validate(document: LocatedDocument) -> LoadedSpec[PartSpec]:
    kind = document.data.get("kind", "robot")
    if not isinstance(kind, str) or kind not in SPEC_KINDS:  # a list or a mapping is no kind
        raise SpecError(
            document.problem(KIND, f"unknown spec kind '{kind}'; use one of {', '.join(SPEC_KINDS)}")
        )
    return validate(document, SPEC_KINDS[kind])


def load_documents(
    documents: Iterable[LocatedDocument], parents: Parents | None = None
) -> list[LoadedSpec[PartSpec]]:
    """Resolve inheritance and validate a batch of parsed documents; all problems in one error."""
    documents = list(documents)
    batch = {d.data["name"]: d for d in documents if isinstance(d.data.get("name"), str)}
    resolver = Resolver(batch, parents or NoParents(), read_document)
    loaded: list[LoadedSpec[PartSpec]] = []
    problems: list[Problem] = []
    for document in documents:
        try:
            loaded.append(_validate(resolver.resolve(document)))
        except AssemblerError as error:
            seen = {p.message for p in problems}
            problems.extend(p for p in error.problems if p.message not in seen)
    if problems:
        raise SpecError(problems)
    return loaded


def load_motors(documents: Iterable[LocatedDocument]) -> list[LoadedSpec[MotorSpec]]:
    """Validate motor spec documents (``kind: motor``); all problems in one error."""
    loaded: list[LoadedSpec[MotorSpec]] = []
    problems: list[Problem] = []
    for document in documents:
        try:
            loaded.append(validate(document, MotorSpec))
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise SpecError(problems)
    return loaded


PLACEMENT_KINDS: tuple[str, ...] = ("scene", "experiment")
"""Kinds of spec file that place registered robots rather than describe a part."""

MOTOR_KIND = "motor"
"""The kind of a motor spec: data that parts' ``motors:`` entries name, not a part."""


@dataclass
class SpecFiles:
    """The spec files found in some files and folders, read with positions."""

    parts: list[LocatedDocument] = field(default_factory=list)
    """Robots, bases and grippers."""

    placements: list[LocatedDocument] = field(default_factory=list)
    """Scenes and experiments (found in folders, or given)."""

    motors: list[LocatedDocument] = field(default_factory=list)
    """Motor specs."""

    problems: list[Problem] = field(default_factory=list)
    """Files that could not be read."""


def read_spec_files(paths: Iterable[str | Path]) -> SpecFiles:
    """Every spec file in ``paths`` (files, and folders recursively), read but not validated."""
    found = SpecFiles()
    problems = found.problems
    for given in paths:
        path = Path(given)
        if is_dir(path):  # neither raises for a name too long for the file system: it is no file
            files = spec_files(path)
        elif os.path.lexists(path):
            files = [path]
        else:
            problems.append(Problem(f"no such file or folder: {display_path(path)}"))
            continue
        for file in files:
            try:
                if file is not path:  # found in a folder: a link must not lead out of it
                    confine(file, [path], "spec file ")
                document = read_document(file)
            except AssemblerError as error:
                problems.extend(error.problems)
                continue
            kind = document.data.get("kind")
            if kind == MOTOR_KIND:
                found.motors.append(document)
            else:
                (found.placements if kind in PLACEMENT_KINDS else found.parts).append(document)
    return found


def load_paths(paths: Iterable[str | Path], parents: Parents | None = None) -> list[LoadedSpec[PartSpec]]:
    """Load the part specs in spec files and folders (recursively) together; every problem of every
    file at once (motor specs among them are checked too). Scene and experiment files in folders are
    not parts and are left to their commands."""
    return load_spec_paths(paths, parents)[0]


def load_spec_paths(
    paths: Iterable[str | Path], parents: Parents | None = None
) -> tuple[list[LoadedSpec[PartSpec]], list[LoadedSpec[MotorSpec]]]:
    """The part specs and the motor specs in spec files and folders (recursively), loaded together;
    every problem of every file at once."""
    paths = list(paths)
    found = read_spec_files(paths)
    problems = list(found.problems)
    given = {Path(path).resolve() for path in paths}
    for document in found.placements:
        if Path(document.file).resolve() in given:  # named itself, not found in a folder
            kind = document.data["kind"]
            problems.append(
                document.problem(KIND, f"a {kind} file is not a part spec; use `assembler {kind}`")
            )
    try:
        loaded = load_documents(found.parts, parents)
    except AssemblerError as error:
        problems.extend(error.problems)
        loaded = []
    try:
        motors = load_motors(found.motors)
    except AssemblerError as error:
        problems.extend(error.problems)
        motors = []
    if problems:
        raise SpecError(problems)
    return loaded, motors


def load_string(text: str, parents: Parents | None = None, name: str = "<string>") -> LoadedSpec[PartSpec]:
    """Load one spec from YAML text; relative paths in it are taken from the working directory."""
    document = parse_yaml(text, name)
    resolve_path_fields(document)
    return load_documents([document], parents)[0]
