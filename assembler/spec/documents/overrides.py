"""Dotted overrides (``joint_defaults.damping=0.2``, ``init_qpos[3]=-2.0``) applied to a spec document.

An override edits the spec's merged YAML mapping (``extends`` already resolved) before it is
validated, so its value is typed and checked by the same schema as a value written in the file.
The path is walked through the schema first, so a typo lists the keys that exist at that level.
Problems caused by an override name the override (``--set init_qpos[7]``), not the spec's line.
"""

from __future__ import annotations

import copy
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any, TypeVar

from pydantic import BaseModel

from assembler.errors import Location, Problem, SpecError
from assembler.files.limits import MAX_YAML_DEPTH
from assembler.files.paths import resolve_model_path
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.documents.problems import LoadedSpec, validate
from assembler.spec.documents.reading import PATH_FIELDS
from assembler.spec.documents.schema_walk import SchemaMiss, step
from assembler.spec.documents.yaml_reader import parse_yaml_value
from assembler.spec.fieldpath import FieldPath, FieldPathError

FIXED_FIELDS: tuple[str, ...] = ("name", "extends", "kind", "morphology")
"""Fields that choose the class itself; changing them is a new spec (``extends:``), not an override."""

M = TypeVar("M", bound=BaseModel)


@dataclass(frozen=True)
class Override:
    """One value for one field path, and how an error about it names it."""

    path: FieldPath
    value: Any
    label: str = "override "
    """Written before the path in errors: ``--set ``, ``robots[0].overrides.``."""

    location: Location | None = None
    """Where the override was written (an experiment file), if anywhere."""

    @property
    def key(self) -> str:
        """The path as users write it: ``init_qpos[3]``."""
        return str(self.path)

    def problem(self, message: str, path: FieldPath | None = None) -> Problem:
        """A problem about this override (or a field below it), named as the user wrote it."""
        return Problem(message, self.location, self.label + str(self.path if path is None else path))


Overrides = Mapping[str, Any] | Iterable[str | Override] | None
"""``{"joint_defaults.damping": 0.2}``, ``["init_qpos[3]=-2.0"]``, parsed overrides, or None."""


def parse_path(text: str, label: str = "override ", location: Location | None = None) -> FieldPath:
    """``init_qpos[3]`` -> its :class:`FieldPath`; a malformed path is a :class:`SpecError`."""
    try:
        return FieldPath.parse(text)
    except FieldPathError as error:
        raise SpecError(Problem(str(error), location, label + text)) from None


def _shallow(value: Any, where: str) -> Any:
    """``value`` (given in Python), if it nests no deeper than a spec file may
    (:data:`~assembler.files.limits.MAX_YAML_DEPTH`): deeper, every later step would recurse past
    Python's limit (a RecursionError, not a line)."""
    pending = [(value, 1)]
    while pending:
        item, depth = pending.pop()
        if isinstance(item, (list, tuple, dict)):
            if depth > MAX_YAML_DEPTH:
                raise SpecError(
                    Problem(f"nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels", None, where)
                )
            children = item.values() if isinstance(item, dict) else item
            pending += [(child, depth + 1) for child in children]
    return value


def parse_override(text: str, label: str = "override ") -> Override:
    """``PATH=VALUE``, the value read as YAML (``0.2``, ``[0.1, 0.2]``, ``null``, ``{inverse_index: 3}``)."""
    key, sep, raw = text.partition("=")
    if not sep or not key.strip():
        raise SpecError(
            Problem(
                f"expected PATH=VALUE (e.g. joint_defaults.damping=0.2), got '{text}'", None, label.strip()
            )
        )
    path = parse_path(key.strip(), label)
    # Read as a spec file's values are: bounded nesting (a deep value was a RecursionError), plain tags.
    return Override(path, parse_yaml_value(raw, label + key.strip()), label)


def parse_overrides(overrides: Overrides, label: str = "override ") -> list[Override]:
    """Every accepted form of overrides as a list of :class:`Override`, in order."""
    if overrides is None:
        return []
    if isinstance(overrides, Mapping):
        return [
            Override(parse_path(str(key), label), _shallow(value, label + str(key)), label)
            for key, value in overrides.items()
        ]
    if isinstance(overrides, str):
        overrides = [overrides]
    return [item if isinstance(item, Override) else parse_override(item, label) for item in overrides]


def _assign(data: dict[str, Any], model: type[BaseModel], override: Override) -> None:
    """Put ``override.value`` at its path in ``data``, creating mappings the file left out."""
    path = override.path
    if path and path[0] in FIXED_FIELDS:
        raise SchemaMiss(
            f"'{path[0]}' chooses the class and cannot be overridden; write a spec with extends:"
        )
    annotation: Any = model
    container: Any = data
    for depth, part in enumerate(path):
        here = FieldPath(path[:depth])
        annotation = step(annotation, part, here, container, hidden=FIXED_FIELDS if not here else ())
        if depth == len(path) - 1:
            value = override.value
            if depth == 0 and part in PATH_FIELDS and isinstance(value, str) and value:
                value = resolve_model_path(value, None)  # relative to the working directory
            container[part] = copy.deepcopy(value)
            return
        current = container.get(part) if isinstance(part, str) else container[part]
        if isinstance(path[depth + 1], str) and not isinstance(current, dict):
            # a mapping the file leaves out, or a rule given as a number now given as a mapping
            current = {}
            container[part] = current
        container = current


def apply_overrides(
    document: LocatedDocument, model: type[BaseModel], overrides: Sequence[Override]
) -> LocatedDocument:
    """A copy of ``document`` with the overrides applied; every bad path is reported at once."""
    data = copy.deepcopy(document.data)
    fields, values = dict(document.fields), dict(document.values)
    problems: list[Problem] = []
    for override in overrides:
        try:
            _assign(data, model, override)
        except SchemaMiss as miss:
            problems.append(override.problem(str(miss)))
            continue
        except SpecError as error:  # e.g. an mjcf path outside the allowed folders
            problems += [override.problem(p.message) for p in error.problems]
            continue
        # The file's positions no longer describe these values; errors name the override instead.
        for marks in (fields, values):
            for path in [p for p in marks if FieldPath(p).is_within(override.path)]:
                del marks[path]
    if problems:
        raise SpecError(problems)
    return LocatedDocument(
        data=data,
        file=document.file,
        folder=document.folder,
        path=document.path,
        fields=fields,
        values=values,
        origins=document.origins,
    )


def blame(problem: Problem, overrides: Sequence[Override], note: bool = True) -> Problem:
    """Name the override a problem comes from; others keep the spec's position (and, with ``note``,
    say that overrides were applied, since one may have caused it indirectly)."""
    if isinstance(problem.path, FieldPath):
        for override in reversed(overrides):  # the last override of a path is the one that counts
            if problem.path.is_within(override.path):
                return Problem(problem.message, override.location, override.label + str(problem.path))
    if not note:
        return problem
    keys = ", ".join(o.key for o in overrides)
    return Problem(f"{problem.message} (with the overrides {keys})", problem.location, problem.path)


def overridden_spec(loaded: LoadedSpec[M], overrides: Sequence[Override]) -> LoadedSpec[M]:
    """The spec ``loaded`` describes with ``overrides`` applied and validated."""
    model = type(loaded.spec)
    document = apply_overrides(loaded.document, model, overrides)
    try:
        return validate(document, model)
    except SpecError as error:
        raise SpecError([blame(p, overrides) for p in error.problems]) from None
