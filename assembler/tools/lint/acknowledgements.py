"""RA002 and ``lint.acknowledge``: findings a spec's authors accept, reported as such, never hidden.

A part's spec may acknowledge a code with a reason (robosuite's Robotiq 85 starts with its fingers
outside their ranges, and robosuite's own model does so too). Each finding of that code about the
part keeps its place in the report, marked acknowledged with the reason, and no longer fails lint.
A finding is about a gripper or base when it names that part or only elements of it; about a robot
when it names the robot or any of its elements (the robot's spec answers for the assembly it makes
with its parts, e.g. its arm inside its default mount). An acknowledgement that
matches no finding is itself reported (RA002): the file or the check changed, and it should go.
"""

from __future__ import annotations

import dataclasses
import re
from collections.abc import Iterator

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.models import PartModel, RobotModel
from assembler.spec.fieldpath import FieldPath

_NAME = re.compile(r"[A-Za-z0-9_:.\-]+")


def concerns(target: LintTarget, part: PartModel, finding: Finding) -> bool:
    """Whether ``finding`` is about ``part`` (see the module docstring)."""
    names = _NAME.findall(finding.subject)
    if type(part).__name__ in names:
        return True
    owners = {owner for name in names if (owner := target.part_of(name)) is not None}
    if isinstance(part, RobotModel) and part is target.parts[0]:
        return part in owners
    return owners == {part}


def acknowledge(target: LintTarget, findings: list[Finding]) -> list[Finding]:
    """``findings`` with those the target's parts acknowledge marked, plus an RA002 per
    acknowledgement that matched none."""
    marked = list(findings)
    for part in target.parts:
        for index, accepted in enumerate(part.spec.lint.acknowledge):
            matched = False
            for number, finding in enumerate(marked):
                if (
                    finding.code == accepted.code
                    and finding.acknowledged is None
                    and concerns(target, part, finding)
                ):
                    marked[number] = dataclasses.replace(finding, acknowledged=accepted.reason)
                    matched = True
            if not matched:
                marked.extend(_unmatched(target, part, index, accepted.code))
    return marked


def _unmatched(target: LintTarget, part: PartModel, index: int, code: str) -> Iterator[Finding]:
    yield Finding(
        code="RA002",
        severity="warning",
        subject=type(part).__name__,
        why=f"lint.acknowledge[{index}] accepts {code}, but lint finds no {code} about this part",
        fix="delete the acknowledgement: the file or the check has changed",
        location=target.spec_location(part, FieldPath(("lint", "acknowledge", index))),
    )
