"""Which body part a joint belongs to: declared in the spec, or robosuite's name rules.

robosuite classifies by substring on *prefixed* names, so a prefix such as ``leg0_`` decides the
group. Here the rules see only the name written in the MJCF, and a spec can declare groups
outright; actuators follow the joint they drive.
"""

from __future__ import annotations

import re
from collections.abc import Sequence

ROBOSUITE_RULES: tuple[tuple[str, str], ...] = (
    ("torso", "torso"),
    ("mobile", "base"),
    ("head", "head"),
    ("leg", "legs"),
)
"""(substring, group), first match wins, in robosuite's order (manipulator_model.py)."""

_LEFT = re.compile(r"(^|[^a-z])(left|l)([^a-z]|$)", re.IGNORECASE)


def robosuite_group(name: str) -> str | None:
    """torso, base, head or legs by robosuite's substring rules; None for an arm joint."""
    for substring, group in ROBOSUITE_RULES:
        if substring in name:
            return group
    return None


def arm_side(name: str, arms: Sequence[str]) -> str:
    """The arm a joint belongs to when the spec does not say: 'left' for names like
    ``left_s0``, ``arm_left_1`` or ``l_arm_elbow`` on a bimanual robot, otherwise 'right'."""
    if "left" in arms and _LEFT.search(name):
        return "left"
    return "right"


class PerArm(list[str]):
    """All arm joints (or actuators) in order, as robosuite's flat list; ``lst["right"]`` is one arm's."""

    def __init__(self, by_arm: dict[str, list[str]]) -> None:
        super().__init__(name for names in by_arm.values() for name in names)
        self.by_arm = by_arm

    def __getitem__(self, key):  # type: ignore[no-untyped-def]
        if isinstance(key, str):
            return self.by_arm[key]
        return super().__getitem__(key)
