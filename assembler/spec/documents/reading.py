"""Reading a spec file of any kind: its text, its positions, its file references, its validation.

:func:`read_validated` is the one way every file kind (robot, base, gripper, scene, experiment)
becomes a validated spec: read the YAML with positions, resolve ``extends`` when the kind has it,
check the result with the kind's pydantic model, and report every problem with its position.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import TypeVar

from pydantic import BaseModel

from assembler.errors import Problem, SpecError
from assembler.files.paths import display_path, resolve_model_path
from assembler.spec.documents.inheritance import NoParents, Parents, Resolver
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.documents.problems import LoadedSpec, validate
from assembler.spec.documents.yaml_reader import parse_yaml, read_yaml_text
from assembler.spec.fieldpath import FieldPath

PATH_FIELDS: tuple[str, ...] = ("mjcf", "urdf")
"""Top-level fields holding file references, resolved against the folder of the file that wrote them."""

M = TypeVar("M", bound=BaseModel)


def resolve_path_fields(document: LocatedDocument) -> None:
    """Make the document's file references absolute; each must stay in its folder or a trusted one."""
    problems: list[Problem] = []
    for key in PATH_FIELDS:
        value = document.data.get(key)
        if isinstance(value, str) and value:
            try:
                document.data[key] = resolve_model_path(value, document.folder)
            except SpecError as error:
                path = FieldPath((key,))
                problems.extend(Problem(p.message, document.where(path), path) for p in error.problems)
    if problems:
        raise SpecError(problems)


def read_document(path: Path) -> LocatedDocument:
    """A spec file's YAML with positions, its file references made absolute."""
    shown = display_path(path)
    try:
        stat: os.stat_result | None = path.stat()  # before reading: a change while reading shows
    except OSError:
        stat = None  # reading says what is wrong
    document = parse_yaml(read_yaml_text(path, shown), shown, path.parent.resolve())
    document.path = path.resolve()
    if stat is not None:
        document.origins = ((str(document.path), stat.st_size, stat.st_mtime_ns),)
    resolve_path_fields(document)
    return document


def read_validated(path: str | Path, model: type[M], parents: Parents | None = None) -> LoadedSpec[M]:
    """A spec file validated by ``model``, its ``extends`` resolved first when the model has one
    (parents found in ``parents``, the registry); every problem in one :class:`SpecError`."""
    document = read_document(Path(path))
    if "extends" in model.model_fields:
        document = Resolver({}, parents or NoParents(), read_document).resolve(document)
    return validate(document, model)
