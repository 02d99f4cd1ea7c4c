"""What changed between two validated specs, field by field, as dotted paths (``init_qpos[3]``).

Specs are compared as the plain data pydantic dumps (every field, defaults included, ``extends``
resolved), so a value moved into a parent spec or written out at its default is no change.
Lists of equal length are compared item by item; a list of numbers that changed length is one
change of the whole list, and items added to or removed from a list of mappings are one each.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Literal

from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import PartSpec

ChangeKind = Literal["changed", "added", "removed"]


@dataclass(frozen=True)
class FieldChange:
    """One spec field that differs: its path, and its value before and after (None when absent)."""

    path: str
    kind: ChangeKind
    before: Any
    after: Any


def _walk(before: Any, after: Any, path: FieldPath, out: list[FieldChange]) -> None:
    if before == after:
        return
    if isinstance(before, dict) and isinstance(after, dict):
        for key in [*before, *(k for k in after if k not in before)]:
            here = path.child(key)
            if key not in after:
                out.append(FieldChange(str(here), "removed", before[key], None))
            elif key not in before:
                out.append(FieldChange(str(here), "added", None, after[key]))
            else:
                _walk(before[key], after[key], here, out)
        return
    if isinstance(before, list) and isinstance(after, list):
        items = [*before, *after]
        if len(before) == len(after) or (items and all(isinstance(x, dict) for x in items)):
            for index in range(max(len(before), len(after))):
                here = path.child(index)
                if index >= len(after):
                    out.append(FieldChange(str(here), "removed", before[index], None))
                elif index >= len(before):
                    out.append(FieldChange(str(here), "added", None, after[index]))
                else:
                    _walk(before[index], after[index], here, out)
            return
    out.append(FieldChange(str(path), "changed", before, after))


def spec_changes(before: PartSpec, after: PartSpec) -> list[FieldChange]:
    """Every field whose validated value differs, in the schema's field order."""
    out: list[FieldChange] = []
    _walk(before.model_dump(mode="json"), after.model_dump(mode="json"), FieldPath(), out)
    return out
