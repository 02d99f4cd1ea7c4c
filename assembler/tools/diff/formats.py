"""A comparison as text for terminals, Markdown for pull-request comments, or JSON for machines."""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from typing import Any

from assembler.files.paths import PACKAGE_SCHEME, display_path
from assembler.spec.documents import PATH_FIELDS
from assembler.tools.diff.compare import Comparison
from assembler.tools.diff.model_diff import ELEMENTS

MODEL_TITLE = "compiled model (robots with their default base and grippers)"


def _number(value: float, digits: int) -> str:
    return f"{value:.{digits}g}"


def _shown(value: Any, digits: int = 6) -> str:
    """A value as a reviewer reads it: short numbers, lists in brackets, absent as ``-``."""
    if value is None:
        return "-"
    if isinstance(value, bool) or not isinstance(value, (int, float, list, dict)):
        return str(value)
    if isinstance(value, (int, float)):
        return _number(float(value), digits)
    if isinstance(value, list) and all(
        isinstance(x, (int, float)) and not isinstance(x, bool) for x in value
    ):
        return "[" + ", ".join(_number(float(x), digits) for x in value) + "]"
    return json.dumps(value, separators=(", ", ": "))


def _pair(before: Any, after: Any) -> tuple[str, str]:
    """Both values, with more digits when six would print them alike."""
    shown = (_shown(before), _shown(after))
    return shown if shown[0] != shown[1] else (_shown(before, 15), _shown(after, 15))


def _spec_value(path: str, value: Any) -> Any:
    """File fields relative to the working directory when inside it (``package://`` kept as written)."""
    if path in PATH_FIELDS and isinstance(value, str) and not value.startswith(PACKAGE_SCHEME):
        return display_path(value)
    return value


def _spec_rows(comparison: Comparison) -> list[tuple[str, str, str]]:
    return [
        (change.path, *_pair(_spec_value(change.path, change.before), _spec_value(change.path, change.after)))
        for change in comparison.spec
    ]


def _model_rows(comparison: Comparison) -> list[tuple[str, str, str, str, str]]:
    return [(c.element, c.name, c.property, *_pair(c.before, c.after)) for c in comparison.model.changed]


def _membership(comparison: Comparison) -> list[tuple[str, str, list[str]]]:
    """("added" | "removed", element kind, names) for every non-empty group."""
    groups = [("added", comparison.model.added), ("removed", comparison.model.removed)]
    return [
        (what, element, table[element])
        for what, table in groups
        for element in ELEMENTS
        if table.get(element)
    ]


def _columns(rows: Sequence[Sequence[str]], indent: str = "  ") -> list[str]:
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return [indent + "  ".join(c.ljust(w) for c, w in zip(row, widths, strict=True)).rstrip() for row in rows]


def _plural(element: str, count: int) -> str:
    return element if count == 1 else f"{element[:-1]}ies" if element.endswith("y") else f"{element}s"


def as_text(comparison: Comparison) -> str:
    """Aligned sections for a terminal."""
    lines = [f"--- {comparison.before.label}", f"+++ {comparison.after.label}"]
    if comparison.identical:
        return "\n".join([*lines, "no differences"]) + "\n"
    spec = _spec_rows(comparison)
    lines += ["", f"spec fields ({len(spec)} changed)"]
    lines += _columns([(path, f"{old} -> {new}") for path, old, new in spec]) if spec else ["  (none)"]
    lines += ["", MODEL_TITLE]
    for what, element, names in _membership(comparison):
        lines.append(
            f"  {'+' if what == 'added' else '-'} {len(names)} {_plural(element, len(names))} {what}: "
            + ", ".join(names)
        )
    rows = _model_rows(comparison)
    lines += _columns([(e, n, p, f"{old} -> {new}") for e, n, p, old, new in rows]) if rows else []
    if comparison.model.empty:
        lines.append("  (no differences)")
    return "\n".join(lines) + "\n"


def _cell(text: str) -> str:
    return text.replace("|", "\\|")


def _table(header: Sequence[str], rows: Sequence[Sequence[str]]) -> list[str]:
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    return lines + ["| " + " | ".join(_cell(c) for c in row) + " |" for row in rows]


def as_markdown(comparison: Comparison) -> str:
    """Headings and tables for a pull-request comment."""
    lines = [f"### `{comparison.before.label}` → `{comparison.after.label}`", ""]
    if comparison.identical:
        return "\n".join([*lines, "No differences."]) + "\n"
    spec = _spec_rows(comparison)
    lines += [f"**Spec fields** ({len(spec)} changed)", ""]
    lines += (
        _table(("field", "before", "after"), [(f"`{p}`", o, n) for p, o, n in spec]) if spec else ["None."]
    )
    lines += ["", f"**{MODEL_TITLE[0].upper()}{MODEL_TITLE[1:]}**", ""]
    for what, element, names in _membership(comparison):
        lines.append(
            f"- {what.title()} {_plural(element, len(names))}: " + ", ".join(f"`{n}`" for n in names)
        )
    if _membership(comparison):
        lines.append("")
    rows = [(e, f"`{n}`", p, o, new) for e, n, p, o, new in _model_rows(comparison)]
    lines += _table(("element", "name", "property", "before", "after"), rows) if rows else []
    if comparison.model.empty:
        lines.append("No differences.")
    return "\n".join(lines).rstrip() + "\n"


def as_json(comparison: Comparison) -> str:
    """One JSON object: both labels, ``identical``, spec changes and model changes, values unrounded."""
    document = {
        "before": comparison.before.label,
        "after": comparison.after.label,
        "identical": comparison.identical,
        "spec": [vars(change) for change in comparison.spec],
        "model": {
            "added": comparison.model.added,
            "removed": comparison.model.removed,
            "changed": [vars(change) for change in comparison.model.changed],
        },
    }
    return json.dumps(document, indent=2) + "\n"


FORMATS: dict[str, Callable[[Comparison], str]] = {"text": as_text, "markdown": as_markdown, "json": as_json}
"""``--format`` choices."""
