"""A located document checked by its pydantic model, every problem translated to the user's terms.

Pydantic reports an error per failed constraint with its own location format; here each becomes
one :class:`~assembler.errors.Problem` at the line and column of the value (or key) concerned,
with our wording for the common cases (unknown key with a suggestion, missing field, a list of the
wrong length), in reading order.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Generic, TypeVar

from pydantic import BaseModel, ValidationError

from assembler.errors import Location, Problem, SpecError
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.documents.schema_walk import keys_at, unknown_key_message
from assembler.spec.fieldpath import FieldPath

M = TypeVar("M", bound=BaseModel)


@dataclass(frozen=True)
class LoadedSpec(Generic[M]):
    """A validated spec and the document it came from (for locating later problems)."""

    spec: M
    document: LocatedDocument

    @property
    def source(self) -> str:
        """Where the spec was written, as ``file:line:col`` of its first line."""
        return str(self.document.start)

    def location(self, path: FieldPath) -> Location:
        """The position of a field's value (or of the closest enclosing field)."""
        return self.document.where(FieldPath(path))

    def problem(self, path: FieldPath, message: str) -> Problem:
        """A problem about a field of this spec, at its position."""
        return self.document.problem(FieldPath(path), message)


def validation_problems(
    error: ValidationError, document: LocatedDocument, model: type[BaseModel]
) -> list[Problem]:
    """One positioned problem per pydantic error, in reading order."""
    problems: list[Problem] = []
    short: dict[FieldPath, int] = {}  # vectors given too few values: path -> values expected
    for item in error.errors():
        path = FieldPath.of_data(item["loc"], document.data)
        kind = item["type"]
        position = item["loc"][-1] if item["loc"] else None
        if kind == "missing" and isinstance(position, int):
            short[path] = max(short.get(path, 0), position + 1)
        elif kind == "missing":
            parent = path.parent
            problems.append(
                Problem(
                    f"missing required field '{path[-1]}'; add it",
                    document.field_location(parent),
                    parent or None,
                )
            )
        elif kind == "extra_forbidden":
            message = unknown_key_message(str(path[-1]), keys_at(model, path.parent))
            problems.append(Problem(message, document.field_location(path), path))
        else:
            problems.append(document.problem(path, item["msg"]))
    for path, expected in short.items():
        given = document.value_at(path)
        count = len(given) if isinstance(given, list) else 0
        problems.append(document.problem(path, f"expected {expected} values, got {count}"))
    return sorted(problems, key=reading_order)


def reading_order(problem: Problem) -> tuple[str, int, int]:
    """Sort key: file, line, column (problems without a position first)."""
    where = problem.location
    if where is None:
        return ("", 0, 0)
    return (where.file, where.line or 0, where.column or 0)


def validate(document: LocatedDocument, model: type[M]) -> LoadedSpec[M]:
    """``document`` checked by ``model``; every problem in one :class:`SpecError`."""
    try:
        spec = model.model_validate(document.data)
    except ValidationError as error:
        raise SpecError(validation_problems(error, document, model)) from None
    return LoadedSpec(spec=spec, document=document)
