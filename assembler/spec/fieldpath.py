"""Where a value sits in a spec document, with one spelling everywhere: ``joints[0].match``.

A :class:`FieldPath` is the tuple of mapping keys and list indexes from the top of a document.
Messages, overrides (``--set init_qpos[3]=...``), positions in files and pydantic's error
locations all meet in this one type, so no code ever compares two spellings of a path.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

_SEGMENT = re.compile(r"(?P<key>[^.\[\]\s=]+)(?P<indexes>(?:\[-?\d+\])*)$")


class FieldPathError(ValueError):
    """Text that is not a field path; the message says what is expected."""


class FieldPath(tuple[str | int, ...]):
    """Mapping keys (text) and list indexes (numbers) from the top of a document."""

    __slots__ = ()

    def __new__(cls, parts: Iterable[str | int] = ()) -> FieldPath:
        return super().__new__(cls, parts)

    @classmethod
    def parse(cls, text: str) -> FieldPath:
        """``init_qpos[3]`` -> ``FieldPath(("init_qpos", 3))``; :class:`FieldPathError` otherwise."""
        parts: list[str | int] = []
        for segment in text.split("."):
            match = _SEGMENT.match(segment)
            if match is None:
                raise FieldPathError("expected a dotted path such as joint_defaults.damping or init_qpos[3]")
            parts.append(match["key"])
            for index in re.findall(r"\[(-?\d+)\]", match["indexes"]):
                if int(index) < 0:
                    raise FieldPathError(f"index {index}: count from 0")
                parts.append(int(index))
        return cls(parts)

    @classmethod
    def of_data(cls, location: Iterable[Any], data: Any) -> FieldPath:
        """A validator's error location (pydantic's ``loc``) as a path in ``data``: the parts that
        are not keys or indexes of the data (names of union branches) are left out."""
        parts: list[str | int] = []
        current = data
        for part in location:
            if isinstance(current, dict) and isinstance(part, str):
                parts.append(part)
                current = current.get(part)  # None below a missing or unknown key
            elif isinstance(current, list) and isinstance(part, int) and part < len(current):
                parts.append(part)
                current = current[part]
        return cls(parts)

    def child(self, part: str | int) -> FieldPath:
        """This path, one level deeper."""
        return FieldPath((*self, part))

    @property
    def parent(self) -> FieldPath:
        """This path, one level up (the top stays the top)."""
        return FieldPath(self[:-1])

    def is_within(self, other: FieldPath) -> bool:
        """True when this path is ``other`` or lies below it."""
        return self[: len(other)] == other

    def __str__(self) -> str:
        text = ""
        for part in self:
            text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
        return text

    def __repr__(self) -> str:
        return f"FieldPath({str(self)!r})"


TOP = FieldPath()
"""The whole document."""
