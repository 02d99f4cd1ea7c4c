"""A part's actuators after the spec's ``actuators:`` entries: which joints each entry drives, and
every actuator with where each of its values came from (``assembler inspect`` prints the table).

One actuator per matched joint (a name or a glob, the rule of ``joints:``); a later entry replaces
an earlier one's on the same joint. A joint that already has an actuator in the file loses it
(``force: true``, the default) or keeps it and gets none (``force: false``). Globs skip joints that
follow another through a joint equality (a URDF ``<mimic>``): their leader's actuator moves them.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field

import mujoco

from assembler.errors import Problem
from assembler.mjcf.actuators import MOVING, ValueOrigin, add_declared_actuator, find_actuator, followers
from assembler.models.joint_rules import SpecProblem, matching_joints, no_match
from assembler.models.motor_rules import Derived
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import ActuatorDeclaration

ACTUATORS = FieldPath(("actuators",))
FROM_FILE = "mjcf"
"""How the table names an actuator the file itself has (MJCF or URDF's ``<mujoco>``) and no entry replaced."""


@dataclass(frozen=True)
class ActuatorRecord:
    """One actuator of the part: its joint, kind, the entry that made it, its values and their sources."""

    name: str
    joint: str | None
    """The joint it drives, or None for an actuator of the file that drives something else (a tendon)."""

    type: str
    """position, velocity, motor or general for a declared actuator; ``file`` for the file's own."""

    entry: int | None = None
    """The index of the ``actuators:`` entry that made it; None for the file's own actuator."""

    values: Mapping[str, tuple[str, ValueOrigin | str]] = field(default_factory=dict)
    """Value name -> (value as text, its source), e.g. ``ctrlrange: ("[-2.9, 2.9]", "joint range")``."""

    section: str = "actuators"
    """The spec section whose entry made it: ``actuators`` or ``motors``."""

    derivations: tuple[tuple[str, Derived], ...] = ()
    """For a motor's actuator: each value derived from the motor spec, by name (``inspect`` shows them)."""

    note: str = ""
    """What the actuator replaced, if anything (a motor's actuator replaces the joint's own)."""

    @property
    def source(self) -> str:
        """``spec actuators[i]`` (or ``motors[i]``), or ``mjcf`` for the file's own actuator."""
        return FROM_FILE if self.entry is None else f"spec {self.section}[{self.entry}]"


def _file_records(spec: mujoco.MjSpec) -> list[ActuatorRecord]:
    return [
        ActuatorRecord(a.name, a.target if a.trntype == mujoco.mjtTrn.mjTRN_JOINT else None, "file")
        for a in spec.actuators
    ]


def _assignments(
    spec: mujoco.MjSpec, entries: Sequence[ActuatorDeclaration], problem: SpecProblem
) -> tuple[dict[str, int], list[Problem]]:
    """Joint -> index of the entry that drives it (the last matching one), in joint order; problems."""
    names = [j.name for j in spec.joints if j.type != mujoco.mjtJoint.mjJNT_FREE]
    skipped = followers(spec)
    problems: list[Problem] = []
    chosen: dict[str, int] = {}
    for index, entry in enumerate(entries):
        here = ACTUATORS.child(index).child("match")
        matched = matching_joints(entry.match, names)
        if entry.match not in names:
            matched = [name for name in matched if name not in skipped]
        if not matched:
            problems.append(problem(here, no_match(entry.match, names)))
        for name in matched:
            if spec.joint(name).type not in MOVING:
                message = f"joint '{name}' is a ball joint; actuators here drive hinge and slide joints"
                problems.append(problem(here, message))
            chosen[name] = index
    return {name: chosen[name] for name in names if name in chosen}, problems


def declare_actuators(
    spec: mujoco.MjSpec,
    entries: Sequence[ActuatorDeclaration],
    velocities: Mapping[str, float],
    problem: SpecProblem,
) -> tuple[list[ActuatorRecord], list[Problem]]:
    """Add the declared actuators to ``spec`` (in joint order, after the file's); every actuator of
    the part with its sources, and the problems of the entries (none added when there are any)."""
    if not entries:
        return _file_records(spec), []
    chosen, problems = _assignments(spec, entries, problem)
    if problems:
        return _file_records(spec), problems
    existing = {a.target: a for a in spec.actuators if a.trntype == mujoco.mjtTrn.mjTRN_JOINT}
    records: list[ActuatorRecord] = []
    for joint_name, index in chosen.items():
        entry = entries[index]
        if joint_name in existing:
            if not entry.force:
                continue
            spec.delete(existing.pop(joint_name))
        name = entry.name.replace("{joint}", joint_name)
        if find_actuator(spec, name) is not None:
            message = f"an actuator named '{name}' already exists; give the entry another name"
            problems.append(problem(ACTUATORS.child(index).child("name"), message))
            continue
        values = add_declared_actuator(spec, name, joint_name, entry, velocities)
        records.append(ActuatorRecord(name, joint_name, entry.type, index, values))
    added = {record.name for record in records}
    return [r for r in _file_records(spec) if r.name not in added] + records, problems
