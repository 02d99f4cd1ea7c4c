"""The spec ``assembler new`` writes, as ordered top-level fields each with the comments that say
what was guessed and what is left to decide; :func:`spec_text` turns them into YAML."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import yaml

GUESS = "guess"
"""A value read off the file's tree, names or compile: check it."""

DECIDE = "decide"
"""Something the file cannot tell: the comment names the field to set."""


@dataclass
class Entry:
    """One top-level field of the spec and its comment lines (``guess: ...``, ``decide: ...``)."""

    key: str
    value: Any
    notes: list[str] = field(default_factory=list)
    item_notes: list[str] = field(default_factory=list)
    """For a list of mappings: one comment per item, written above it, the items then written as
    blocks (``mjcf_fixes``: what each deletion removes and where it is)."""

    def guess(self, text: str) -> Entry:
        self.notes.append(f"{GUESS}: {text}")
        return self

    def decide(self, text: str) -> Entry:
        self.notes.append(f"{DECIDE}: {text}")
        return self


def _flow(value: Any) -> str:
    text: str = yaml.safe_dump(value, default_flow_style=True, width=10**6, sort_keys=False)
    return text.strip().removesuffix("...").strip()


def _wrap(text: str, width: int = 106) -> list[str]:
    """A comment's text as ``# `` lines of at most ``width`` characters."""
    lines, line = [], ""
    for word in text.split():
        if line and len(line) + 1 + len(word) > width - 2:
            lines.append(line)
            line = "  " + word if lines or line.startswith("  ") else word
            continue
        line = f"{line} {word}" if line else word
    lines.append(line)
    return [f"# {item}" for item in lines]


def _block_lines(key: str, items: list[dict[str, Any]], notes: list[str]) -> list[str]:
    lines = [f"{key}:"]
    for item, note in zip(items, notes, strict=True):
        lines += [f"  {line}" for line in _wrap(note, 104)]
        for index, (name, value) in enumerate(item.items()):
            lines.append(("  - " if index == 0 else "    ") + f"{name}: {_flow(value)}")
    return lines


def _value_lines(entry: Entry) -> list[str]:
    key, value = entry.key, entry.value
    if entry.item_notes:
        return _block_lines(key, value, entry.item_notes)
    if isinstance(value, list) and value and all(isinstance(item, dict) for item in value):
        return [f"{key}:", *(f"  - {_flow(item)}" for item in value)]
    if isinstance(value, dict) and value and any(isinstance(item, (list, dict)) for item in value.values()):
        return [f"{key}:", *(f"  {_flow({name: item})[1:-1]}" for name, item in value.items())]
    return [f"{key}: {_flow(value)}"]


def spec_text(header: list[str], entries: list[Entry]) -> str:
    """The spec's YAML: the header comment, then each field after its comments."""
    lines = [f"# {line}" if line else "#" for line in header]
    for entry in entries:
        if entry.notes:
            lines.append("")
            for note in entry.notes:
                lines += _wrap(note)
        lines += _value_lines(entry)
    return "\n".join(lines) + "\n"


def short(names: tuple[str, ...] | list[str], limit: int = 6) -> str:
    """The first ``limit`` names joined, and how many more."""
    shown = ", ".join(names[:limit])
    return shown + (f" and {len(names) - limit} more" if len(names) > limit else "")
