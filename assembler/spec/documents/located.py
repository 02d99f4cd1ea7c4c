"""A parsed spec document: plain data plus where each field and value was written.

Every file kind (robot, base, gripper, scene, experiment) is read into a :class:`LocatedDocument`,
so every problem found later (by the schema, by reference checks, by MuJoCo) can point at the
line and column a reviewer must change.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from assembler.errors import Location, Problem
from assembler.spec.fieldpath import TOP, FieldPath


@dataclass
class LocatedDocument:
    """A YAML mapping, the position of each field in it, and the folder its file references start from."""

    data: dict[str, Any]
    file: str
    """The file as shown in messages (relative to the working directory when inside it)."""

    folder: Path | None = None
    """The folder relative file references in the document are taken from (None: the working directory)."""

    path: Path | None = None
    """The file the document was read from, resolved (None for text given directly)."""

    origins: tuple[tuple[str, int, int], ...] = ()
    """(file, size, mtime_ns when read) of every file this document's data came from: its own, then
    its parents' (``extends``). Request records (:mod:`assembler.cache.requests`) check them."""

    fields: dict[FieldPath, Location] = field(default_factory=dict)
    """Where each field is written: a mapping entry's key, a list item's value, the document's start."""

    values: dict[FieldPath, Location] = field(default_factory=dict)
    """Where each mapping entry's (non-empty) value starts."""

    def field_location(self, path: FieldPath) -> Location:
        """The position of ``path``'s key, or of the deepest enclosing field that has one."""
        for end in range(len(path), -1, -1):
            mark = self.fields.get(FieldPath(path[:end]))
            if mark is not None:
                return mark
        return Location(self.file, 1, 1)

    def where(self, path: FieldPath) -> Location:
        """The position of ``path``'s value, else of its key or enclosing field: what a message about
        the value points at."""
        return self.values.get(path) or self.field_location(path)

    def problem(self, path: FieldPath, message: str) -> Problem:
        """A problem about the value at ``path``, located in this document."""
        return Problem(message, self.where(path), path or None)

    def value_at(self, path: FieldPath) -> Any:
        """The data at ``path`` (KeyError/IndexError when it is absent)."""
        value: Any = self.data
        for part in path:
            value = value[part]
        return value

    @property
    def start(self) -> Location:
        """Where the document starts."""
        return self.field_location(TOP)
