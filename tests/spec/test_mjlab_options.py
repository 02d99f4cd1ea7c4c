"""A robot spec's ``mjlab:`` block: its ``collisions`` entries are refused at their line when malformed.

Whether a pattern matches a geom of the robot is checked where the robot is known (tests/mjlab).
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from assembler.errors import SpecError
from assembler.files.paths import display_path
from assembler.spec.schema.robot import RobotSpec
from assembler.spec.spec_files import load_paths

Write = Callable[[str, str], Path]

HEAD = "name: A\nmjcf: a.xml\nmjlab:\n  collisions:\n"

# Each row: the collisions entry (YAML at line 5), the exact message expected (after "<file>:").
INVALID_COLLISIONS = [
    pytest.param(
        "    - geoms: ['(left|right_foot']\n      contype: 0\n",
        "5:15: mjlab.collisions[0].geoms[0]: '(left|right_foot' is not a regular expression: "
        "missing ), unterminated subpattern at position 0",
        id="regex-that-does-not-compile",
    ),
    pytest.param(
        "    - geoms: []\n      contype: 0\n",
        "5:14: mjlab.collisions[0].geoms: List should have at least 1 item after validation, not 0",
        id="no-pattern",
    ),
    pytest.param(
        "    - geoms: ['.*']\n",
        "5:7: mjlab.collisions[0]: the entry for ['.*'] sets nothing; give one of contype, conaffinity, "
        "condim, priority, friction, solref, solimp, margin, gap, solmix",
        id="sets-nothing",
    ),
    pytest.param(
        "    - geoms: ['.*']\n      solref: [0.02, -1]\n",
        "6:15: mjlab.collisions[0].solref: expected two positive numbers (time constant, damping ratio) "
        "or two that are not (-stiffness, -damping), got [0.02, -1.0]",
        id="mixed-solref",
    ),
    pytest.param(
        "    - geoms: ['.*']\n      solimp: [0.9, 0.95, 0.001, 0.5, 0.5]\n",
        "6:15: mjlab.collisions[0].solimp: power must be >= 1, got 0.5",
        id="solimp-out-of-range",
    ),
    pytest.param(
        "    - geoms: ['.*']\n      condim: 2\n",
        "6:15: mjlab.collisions[0].condim: Input should be 1, 3, 4 or 6",
        id="condim",
    ),
    pytest.param(
        "    - geoms: ['.*']\n      contype: true\n",
        "6:16: mjlab.collisions[0].contype: expected a number, got true",
        id="bool-bitmask",
    ),
]


@pytest.mark.parametrize(("entry", "expected"), INVALID_COLLISIONS)
def test_a_malformed_collisions_entry_is_one_line_at_its_position(
    write: Write, entry: str, expected: str
) -> None:
    path = write("specs/bad.yaml", HEAD + entry)
    with pytest.raises(SpecError) as caught:
        load_paths([path])
    assert str(caught.value) == f"{display_path(path)}:{expected}"


def test_collisions_and_the_feet_shorthand_validate_together(write: Write) -> None:
    path = write(
        "specs/good.yaml",
        HEAD
        + "    - {geoms: ['.*_collision.*'], contype: 1, condim: 1, solref: [0.01, 1], friction: [1, 0.005]}\n"
        "  foot_friction: 0.6\n  foot_condim: 3\n",
    )
    (loaded,) = load_paths([path])
    assert isinstance(loaded.spec, RobotSpec)
    mjlab = loaded.spec.mjlab
    (entry,) = mjlab.collisions
    assert entry.geoms == [".*_collision.*"] and entry.friction == (1.0, 0.005) and entry.conaffinity is None
    assert (mjlab.foot_friction, mjlab.foot_condim) == (0.6, 3)
