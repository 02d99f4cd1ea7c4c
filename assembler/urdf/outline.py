"""One streaming pass over a URDF before any tree is built: the limits, and the lines we report.

expat reads the text once and builds nothing (:func:`assembler.files.plain_xml.stream`). It stops
at the limits of :mod:`assembler.files.limits` (elements nested deeper than :data:`MAX_URDF_DEPTH`,
more links or joints than :data:`MAX_URDF_LINKS`), finds two links or two joints of one name (MuJoCo's import
or our own post-processing would otherwise fail with a traceback), and records the line of every
element the messages name: meshes, joints and the children of the ``<mujoco>`` extension element.
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field

from assembler.errors import MjcfError, Problem
from assembler.files.limits import MAX_URDF_DEPTH, MAX_URDF_LINKS
from assembler.files.plain_xml import StopReading, stream

NAMED: tuple[str, ...] = ("link", "joint")
"""Top-level elements whose names must be unique (MuJoCo names its bodies and joints after them)."""


@dataclass
class Outline:
    """What the pass found: lines per element path (below the root), and the extension's children."""

    lines: dict[str, list[int]]
    extension: list[tuple[str, int]] = field(default_factory=list)
    """``(tag, line)`` of each child of the top-level ``<mujoco>`` element."""


def outline(data: bytes, shown: str, paths: Collection[str]) -> Outline:
    """The lines of the elements at ``paths``; :class:`MjcfError` at a limit or for a repeated name."""
    found = Outline({path: [] for path in paths})
    stack: list[str] = []
    first: dict[tuple[str, str], int] = {}
    problems: list[Problem] = []
    counts = dict.fromkeys(NAMED, 0)  # top-level <link> and <joint> elements so far

    def start(name: str, attributes: dict[str, str], line: int) -> None:
        stack.append(name)
        if len(stack) > MAX_URDF_DEPTH:
            raise StopReading(
                f"{shown}:{line}: elements nest deeper than the limit of {MAX_URDF_DEPTH} levels; "
                "a URDF nests a few levels deep"
            )
        here = "/".join(stack[1:])
        if here in found.lines:
            found.lines[here].append(line)
        if len(stack) == 3 and stack[1] == "mujoco":
            found.extension.append((name, line))
        if len(stack) != 2 or name not in NAMED:
            return
        counts[name] += 1
        if counts[name] > MAX_URDF_LINKS:  # a tree of links has one joint fewer: one limit bounds both
            raise StopReading(
                f"{shown}:{line}: more than {MAX_URDF_LINKS} {name}s, the limit (MuJoCo cannot compile a "
                "chain of bodies much deeper); a robot has a few dozen"
            )
        key = (name, attributes.get("name", ""))
        if not key[1]:
            return  # an unnamed joint is refused after the import, with what to do
        if key in first:
            problems.append(
                Problem(
                    f"{shown}:{line}: a second {name} named '{key[1]}' (the first is on line {first[key]}); "
                    f"{name} names must be unique"
                )
            )
        else:
            first[key] = line

    def end(_: str) -> None:
        stack.pop()

    stream(data, shown, start, end)
    if problems:
        raise MjcfError(problems)
    return found
