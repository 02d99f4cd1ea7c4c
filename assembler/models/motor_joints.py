"""A part's ``motors:`` entries applied: which joints each motor drives, their values, their actuators.

Precedence, stated once: for a motor-driven joint each of armature, damping and frictionloss comes
from the spec's own ``joints:`` entry for that joint (or the joint the spec adds), else the motor,
else the model file, else 0. The default rules (robosuite's frictionloss 0.1, damping 0.1, armature
5/(i+1)) apply only to joints no motor drives.

A motor's actuator replaces the joint's own (the file's, or an ``actuators:`` entry's), and says so
in ``assembler inspect``: a joint has one motor. A later ``motors:`` entry replaces an earlier one on
the same joint; globs skip joints that follow another through a joint equality (a URDF ``<mimic>``).
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco

from assembler.errors import Problem, RegistryError
from assembler.mjcf.actuators import MOVING, MotorActuation, add_motor_actuator, find_actuator, followers
from assembler.models.actuator_table import ActuatorRecord
from assembler.models.joint_rules import JointTable, JointValue, SpecProblem, matching_joints, no_match
from assembler.models.motor_rules import Derived, Drive
from assembler.models.motor_table import MOTORS
from assembler.models.provenance import Provenance
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import JointMotor

MOTORS_FIELD = FieldPath(("motors",))

MOTOR_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature")
"""The joint attributes a motor gives."""

KEPT_ORIGINS = ("override", "added")
"""Sources of a joint value that a motor does not replace: the spec's own word for that joint."""


def _control_problem(drive: Drive) -> str | None:
    """Why the motor cannot drive its entry's control, if it cannot."""
    name, control = drive.motor.name, drive.entry.control
    if control == "voltage" and drive.voltage_model() is None:
        return (
            f"voltage control needs the motor's voltage, torque_constant and resistance (or voltage, "
            f"stall_torque and no_load_speed); motor '{name}' does not give them"
        )
    if control in ("torque", "position") and drive.torque_limit() is None:
        return (
            f"{control} control needs a torque limit: motor '{name}' gives no peak_torque, stall_torque, "
            "nor voltage, torque_constant and resistance; add them, or use control: null"
        )
    return None


def motor_drives(
    mjspec: mujoco.MjSpec,
    entries: Sequence[JointMotor],
    problem: SpecProblem,
    names: Sequence[str] | None = None,
) -> tuple[dict[str, Drive], list[Problem]]:
    """Joint -> the drive of the last entry matching it (in joint order); every problem of the entries.
    ``names``: the joints to match (default: ``mjspec``'s, free joints excluded); a joint ``mjspec``
    lacks (one the spec adds) is taken as a hinge or slide."""
    if names is None:
        names = [j.name for j in mjspec.joints if j.type != mujoco.mjtJoint.mjJNT_FREE]
    skipped = followers(mjspec)
    problems: list[Problem] = []
    chosen: dict[str, Drive] = {}
    for index, entry in enumerate(entries):
        here = MOTORS_FIELD.child(index)
        try:
            motor = MOTORS.lookup(entry.motor).spec
        except RegistryError as error:
            problems += [problem(here.child("motor"), p.message) for p in error.problems]
            continue
        drive = Drive(motor, entry, index)
        reason = _control_problem(drive)
        if reason is not None:
            problems.append(problem(here.child("control"), reason))
            continue
        matched = matching_joints(entry.match, names)
        if entry.match not in names:
            matched = [name for name in matched if name not in skipped]
        if not matched:
            problems.append(problem(here.child("match"), no_match(entry.match, names)))
        for name in matched:
            joint = mjspec.joint(name)
            if joint is not None and joint.type not in MOVING:
                message = f"joint '{name}' is a ball joint; a motor drives a hinge or a slide joint"
                problems.append(problem(here.child("match"), message))
            chosen[name] = drive
    return {name: chosen[name] for name in names if name in chosen}, problems


def _motor_value(drive: Drive, derived: Derived) -> JointValue:
    source = Provenance(
        "motor", index=drive.index, motor=drive.motor.name, formula=derived.formula, numbers=derived.numbers
    )
    return JointValue(derived.value, source)


def apply_motor_values(table: JointTable, drives: dict[str, Drive]) -> None:
    """Each motor-driven joint's armature, damping and frictionloss, by the precedence above."""
    for joint, drive in drives.items():
        values = table.setdefault(joint, {})
        for attribute in MOTOR_ATTRIBUTES:
            current = values.get(attribute)
            if current is not None and current.source.origin in KEPT_ORIGINS:
                continue
            derived: Derived | None = getattr(drive, attribute)()
            if derived is not None:
                values[attribute] = _motor_value(drive, derived)
            elif current is not None and current.source.origin == "rule":
                why = f"no {attribute} given; rules skip motor-driven joints"
                values[attribute] = _motor_value(drive, Derived(0.0, why, ""))


def _actuation(drive: Drive) -> tuple[MotorActuation, tuple[tuple[str, Derived], ...]]:
    """The actuator's numbers at the joint, and how each follows from the motor spec."""
    entry, n, eta = drive.entry, drive.gear_ratio, drive.efficiency
    if entry.control == "voltage":
        model = drive.voltage_model()
        assert model is not None  # checked in motor_drives
        kt, resistance = model.torque_constant.value, model.resistance.value
        actuation = MotorActuation(
            "voltage", n, eta, None, model.voltage, kt, resistance, voltage_actuator=entry.voltage_actuator
        )
        return actuation, drive.voltage_derivations(model)
    limit = drive.torque_limit()
    assert limit is not None  # checked in motor_drives
    actuation = MotorActuation(
        str(entry.control), n, eta, limit.value, kp=entry.kp, kv=entry.kv, dampratio=entry.dampratio
    )
    return actuation, (("forcerange", limit),)


JOINT_TRANSMISSION = mujoco.mjtTrn.mjTRN_JOINT

ACTUATOR_TYPE = {"torque": "motor", "position": "position"}


def add_motor_actuators(
    mjspec: mujoco.MjSpec, records: list[ActuatorRecord], drives: dict[str, Drive], problem: SpecProblem
) -> tuple[list[ActuatorRecord], list[Problem]]:
    """Each motor-driven joint's actuator (entries with ``control: null`` add none), replacing the
    joint's own; every actuator of the part, and the problems (a name already taken)."""
    problems: list[Problem] = []
    added: list[ActuatorRecord] = []
    for joint, drive in drives.items():
        entry = drive.entry
        if entry.control is None:
            continue
        replaced = [a for a in mjspec.actuators if a.trntype == JOINT_TRANSMISSION and a.target == joint]
        notes = []
        for actuator in replaced:
            record = next((r for r in records if r.name == actuator.name), None)
            notes.append(f"'{actuator.name}' ({record.source if record is not None else 'mjcf'})")
            mjspec.delete(actuator)
        records = [r for r in records if r.name not in {a.name for a in replaced}]
        name = entry.name.replace("{joint}", joint)
        if find_actuator(mjspec, name) is not None:
            message = f"an actuator named '{name}' already exists; give the entry another name"
            problems.append(problem(MOTORS_FIELD.child(drive.index).child("name"), message))
            continue
        actuation, derivations = _actuation(drive)
        values = add_motor_actuator(mjspec, name, joint, actuation)
        kind = entry.voltage_actuator if entry.control == "voltage" else ACTUATOR_TYPE[str(entry.control)]
        motor = f"motor {drive.motor.name}"
        note = f"replaces {', '.join(notes)}" if notes else ""
        shown = {key: (value, motor) for key, value in values.items()}
        added.append(ActuatorRecord(name, joint, kind, drive.index, shown, "motors", derivations, note))
    return records + added, problems


def voltage_limits(entries: Sequence[JointMotor], records: Sequence[ActuatorRecord]) -> dict[str, Derived]:
    """The part's actuators (by record name, unprefixed) that take volts (a ``motors:`` entry's
    ``control: voltage``) -> the joint torque limit the same entry gives with ``control: torque``,
    ±(peak or stall torque)·N·η: what a controller that writes torques (robosuite's) may ask of them."""
    limits: dict[str, Derived] = {}
    for record in records:
        if record.section != "motors" or record.entry is None or entries[record.entry].control != "voltage":
            continue
        entry = entries[record.entry]
        limit = Drive(MOTORS.lookup(entry.motor).spec, entry, record.entry).torque_limit()
        assert limit is not None  # a motor that can take volts gives a stall torque (motor_drives checked)
        limits[record.name] = limit
    return limits


def derivation_lines(prefix: str, joints: JointTable, records: Sequence[ActuatorRecord]) -> list[str]:
    """Every motor-derived value with its motor, formula and numbers, one line each, for ``inspect``:
    ``robot0_knee  armature 0.00972 = 1.12e-05 kg·m² × 29.5²  (motor M, motors[0])``."""
    lines = []
    for joint, values in joints.items():
        for attribute, value in values.items():
            source = value.source
            if source.origin == "motor" and source.numbers:  # a value the motor gives, not a 0 it leaves
                where = f"(motor {source.motor}, motors[{source.index}]: {source.formula})"
                lines.append(f"{prefix}{joint}  {attribute} {value.value:.6g} = {source.numbers}  {where}")
    for record in records:
        for quantity, derived in record.derivations:
            joint = f"{prefix}{record.joint}" if record.joint is not None else "-"
            where = f"({record.source}: {derived.formula})"
            lines.append(f"{joint}  actuator {prefix}{record.name} {quantity} {derived}  {where}")
        if record.note:
            lines.append(f"{prefix}{record.joint}  actuator {prefix}{record.name} {record.note}")
    return lines
