"""MuJoCo's refusal of an MJCF file, as one located line: the file and line, what is wrong, what to do.

MuJoCo ends its error text with where the element sits: ``Element name 'a1', id 0, line 33`` when
compiling, ``Element 'geom', line 24`` when parsing. Line 0 means an element read from an
``<include>``d file, whose line MuJoCo does not keep; then the element's name stands in for the line.

A file repaired by its spec's ``mjcf_fixes`` is parsed from the repaired text, not from disk, so
MuJoCo's line numbers count lines of that text. :func:`repaired_lines` maps them back to the file
the user can open: ElementTree drops comments and the XML declaration and folds attribute values
that span lines, so the two texts' lines differ. Both texts are read by expat, whose start tags
come in the same order as ``Element.iter()``, which pairs each element with its two lines.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
import xml.parsers.expat
from collections.abc import Callable

LineMap = Callable[[int], "int | None"]
"""MuJoCo's line number -> the line in the file on disk (None: not in that file)."""

_COMPILE_WHERE = re.compile(r"Element name '(?P<name>[^']*)', id \d+(?:, line (?P<line>\d+))?")
_PARSE_WHERE = re.compile(r"Element '(?P<tag>[^']*)', line (?P<line>\d+)")
_REFERENCE = re.compile(
    r"not found|unknown|unrecognized (?:name|object)|missing transmission|must have valid"
)
"""Words of MuJoCo's messages about a name that points at nothing (or at nothing of the right kind)."""

REPAIR_HINT = " (a spec can declare a repair: mjcf_fixes)"


def same_lines(line: int) -> int | None:
    """The line map of a file MuJoCo read from disk itself (0: an included file, no line)."""
    return line or None


def _element_lines(text: bytes) -> list[int]:
    """The line of each element's start tag, in document order."""
    parser = xml.parsers.expat.ParserCreate()
    lines: list[int] = []
    parser.StartElementHandler = lambda *_: lines.append(parser.CurrentLineNumber)
    parser.Parse(text, True)
    return lines


def original_lines(root: ET.Element, text: bytes) -> dict[ET.Element, int]:
    """Each element of ``root`` (parsed from ``text``, not yet edited) -> its line in ``text``."""
    return dict(zip(root.iter(), _element_lines(text), strict=True))


def repaired_lines(root: ET.Element, repaired: str, original: dict[ET.Element, int]) -> LineMap:
    """The line map from the repaired text of ``root`` back to the file (see the module docstring).
    An element the repair created (e.g. a ``<compiler>``) has no line in the file."""
    by_line: dict[int, int | None] = {}
    for element, line in zip(root.iter(), _element_lines(repaired.encode()), strict=True):
        by_line.setdefault(line, original.get(element))
    return lambda line: by_line.get(line)


def _clean(text: str) -> str:
    message = " ".join(text.split())
    for prefix in ("XML Error: ", "Error: "):
        message = message.removeprefix(prefix)
    return message


def _hint(message: str) -> str:
    if "balanceinertia" in message:  # MuJoCo names its own knob; ours is a declared repair
        return (
            "correct the <inertial>, or declare the repair in the spec: mjcf_fixes: [{element: compiler, "
            "set: {balanceinertia: 'true'}, why: ...}]"
        )
    if _REFERENCE.search(message):
        return "correct the name or remove the element"
    return "correct the file"


def refusal_line(error: str, shown: str, lines: LineMap, refusal: str) -> str:
    """One line for MuJoCo's error text ``error`` about the file displayed as ``shown``:
    ``robot.xml:33: <refusal>: <MuJoCo's words> (element 'a1'); <what to do> (... mjcf_fixes)``.

    ``refusal`` says which step refused (reading or compiling); MuJoCo's own words are kept, so a
    reader can search for them.
    """
    where = _COMPILE_WHERE.search(error) or _PARSE_WHERE.search(error)
    text = error[: where.start()] if where else error
    message = _clean(text)
    located = shown
    if where is not None:
        line = lines(int(where.group("line") or 0))
        if line is not None:
            located = f"{shown}:{line}"
        name = where.groupdict().get("name")
        if name and f"'{name}'" not in message:
            message += f" (element '{name}')"
    hint = _hint(message)
    return f"{located}: {refusal}: {message}; {hint}{'' if 'mjcf_fixes' in hint else REPAIR_HINT}"
