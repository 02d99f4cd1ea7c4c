"""Where robosuite's environments put a spec robot: its ``base_xpos_offset`` per arena.

robosuite's environments read ``base_xpos_offset["table"]`` (a function of the table length, called
positionally), ``["bins"]`` and ``["empty"]`` (three numbers each) with no fallback, so a robot
without an entry fails inside the environment with ``KeyError: 'table'``. A spec gives its own
offsets; an arena it leaves out gets the value robosuite gives its own robots of the same arm type:
Panda's (shared by all of robosuite's single arms) or Baxter's (its bimanual robot).
"""

from __future__ import annotations

from typing import Any

from assembler.spec.expressions import evaluate_expression

Offset3 = tuple[float | str, float | str, float | str]
"""An arena offset as a spec writes it (``base_xpos_offset``): numbers, or expressions of the table's
size, already validated."""

DEFAULT_OFFSETS: dict[str, dict[str, Offset3]] = {
    "single": {
        "bins": (-0.5, -0.1, 0.0),
        "empty": (-0.6, 0.0, 0.0),
        "table": ("-0.16 - table_length / 2", 0.0, 0.0),
    },
    "bimanual": {
        "bins": (-0.5, -0.1, 0.0),
        "empty": (-0.29, 0.0, 0.0),
        "table": ("-0.26 - table_length / 2", 0.0, 0.0),
    },
}
"""robosuite's offsets for its own robots by arm type (panda_robot.py, baxter_robot.py)."""


def offsets(spec: Any) -> dict[str, Any]:
    """Per arena, the offset in the shape robosuite reads: the spec's, else robosuite's default for the
    spec's arm type."""
    return in_robosuites_shape(arena_offsets(spec))


def arena_offsets(spec: Any) -> dict[str, Offset3]:
    """Per arena, the offset as written (numbers, or expressions of ``table_length``): the spec's,
    else robosuite's default for the spec's arm type."""
    return {**DEFAULT_OFFSETS.get(str(spec.arm_type), {}), **spec.base_xpos_offset}


def in_robosuites_shape(arenas: dict[str, Offset3]) -> dict[str, Any]:
    """:func:`arena_offsets` as robosuite reads them (``table``'s a function of the table length)."""
    return {arena: _for_robosuite(arena, offset) for arena, offset in arenas.items()}


def _for_robosuite(arena: str, offset: Offset3) -> Any:
    """One arena's offset: ``table``'s a function of the table length, every other three numbers."""

    def resolve(**variables: float) -> tuple[float, float, float]:
        x, y, z = (evaluate_expression(value, variables) for value in offset)
        return (x, y, z)

    if arena == "table":
        return lambda table_length: resolve(table_length=table_length)
    return resolve()
