"""Actuators added to a part's MjSpec: a spec's declared ``actuators:`` entry, and a motor's actuator.

One declared actuator (a spec's ``actuators:`` entry) added to a joint of a part's MjSpec.

Ranges the entry leaves out come from the joint: a position servo's ``ctrlrange`` is the joint's
range, a velocity servo's the URDF's velocity limit, a motor's the joint's effort limit divided by
the gear; ``forcerange`` is the joint's effort limit. Each range comes back with where it came from,
for ``assembler inspect``. Which joints an entry drives is decided in
:mod:`assembler.models.actuator_table`.

A motor's actuator on one joint of a part's MjSpec, from numbers already derived at the joint.

- voltage, ``dcmotor``: MuJoCo's DC motor with ``gear = N``, ``motorconst = (kt, kt)`` (in SI units
  the back-EMF constant equals the torque constant) and ``resistance = R / η``: MuJoCo's model has no
  gearbox efficiency, and ``N·kt/(R/η)·(V − kt·N·ω)`` is exactly ``N·η·kt·(V − kt·N·ω)/R``;
- voltage, ``general``: the same law as a ``general`` actuator, ``gain = N·η·kt/R`` and an affine
  velocity bias ``−N²·η·kt²/R`` (what its basic form computes, for engines without ``dcmotor``);
- torque: a motor whose ctrl is the joint torque, within ±limit;
- position: a position servo whose force is limited to ±limit.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Literal

import mujoco

from assembler.spec.schema import ActuatorDeclaration

MOVING = (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)
TRUE, FALSE = mujoco.mjtLimited.mjLIMITED_TRUE, mujoco.mjtLimited.mjLIMITED_FALSE

Range = tuple[float, float]

ValueOrigin = Literal[
    "spec",
    "joint range",
    "urdf velocity limit",
    "joint effort limit",
    "joint effort limit / gear",
    "no limit known",
]
"""Where a declared actuator's value came from: the entry itself, or the joint it drives."""

GAIN_FIELDS: tuple[str, ...] = ("kp", "kv", "dampratio", "gainprm", "biasprm")


def find_actuator(spec: mujoco.MjSpec, name: str) -> mujoco.MjsActuator | None:
    """The actuator called ``name``, or None. Not ``spec.actuator(name)``: on MuJoCo 3.9 that misses an
    actuator added to a spec since it was parsed or copied (measured: None for a motor's actuator
    that ``spec.actuators`` holds)."""
    return next((actuator for actuator in spec.actuators if actuator.name == name), None)


def followers(spec: mujoco.MjSpec) -> set[str]:
    """Joints that follow another through a joint equality (``joint1`` of each, e.g. a URDF ``<mimic>``)."""
    return {e.name1 for e in spec.equalities if e.type == mujoco.mjtEq.mjEQ_JOINT and e.name2}


def _joint_range(spec: mujoco.MjSpec, joint: mujoco.MjsJoint) -> Range | None:
    low, high = (float(v) for v in joint.range)
    limited = joint.limited == TRUE or (joint.limited != FALSE and low < high and spec.compiler.autolimits)
    if not limited:
        return None
    if spec.compiler.degree and joint.type == mujoco.mjtJoint.mjJNT_HINGE:
        return math.radians(low), math.radians(high)  # controls are in radians whatever the file's unit
    return low, high


def _effort(spec: mujoco.MjSpec, joint: mujoco.MjsJoint) -> Range | None:
    low, high = (float(v) for v in joint.actfrcrange)
    limited = joint.actfrclimited == TRUE or (
        joint.actfrclimited != FALSE and low < high and spec.compiler.autolimits
    )
    return (low, high) if limited else None


def _ranges(
    spec: mujoco.MjSpec, joint: mujoco.MjsJoint, entry: ActuatorDeclaration, velocities: Mapping[str, float]
) -> dict[str, tuple[Range | None, ValueOrigin]]:
    effort = _effort(spec, joint)
    ctrl: tuple[Range | None, ValueOrigin]
    if entry.ctrlrange is not None:
        ctrl = (entry.ctrlrange, "spec")
    elif entry.type == "position":
        ctrl = (_joint_range(spec, joint), "joint range")
    elif entry.type == "velocity" and joint.name in velocities:
        ctrl = ((-velocities[joint.name], velocities[joint.name]), "urdf velocity limit")
    elif entry.type == "motor" and effort is not None:
        ctrl = ((effort[0] / abs(entry.gear), effort[1] / abs(entry.gear)), "joint effort limit / gear")
    else:
        ctrl = (None, "no limit known")
    force: tuple[Range | None, ValueOrigin] = (
        (entry.forcerange, "spec") if entry.forcerange is not None else (effort, "joint effort limit")
    )
    return {"ctrlrange": ctrl, "forcerange": force}


def _padded(values: list[float]) -> list[float]:
    return [*values, *[0.0] * (10 - len(values))]


def _configure(actuator: mujoco.MjsActuator, entry: ActuatorDeclaration) -> None:
    if entry.type == "position":
        kv = entry.kv if entry.kv is not None else -1.0
        dampratio = entry.dampratio if entry.dampratio is not None else -1.0
        actuator.set_to_position(kp=entry.kp or 0.0, kv=kv, dampratio=dampratio)
    elif entry.type == "velocity":
        actuator.set_to_velocity(kv=entry.kv or 0.0)
    elif entry.type == "motor":
        actuator.set_to_motor()
    else:
        actuator.gaintype = mujoco.mjtGain.mjGAIN_FIXED
        actuator.gainprm = _padded(list(entry.gainprm or []))
        if entry.biasprm is not None:
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm = _padded(list(entry.biasprm))
    actuator.gear = [entry.gear, 0, 0, 0, 0, 0]


def range_text(value: Range | None) -> str:
    """``[low, high]`` as ``inspect`` shows it, or ``unlimited``."""
    return "unlimited" if value is None else f"[{value[0]:.6g}, {value[1]:.6g}]"


def add_declared_actuator(
    spec: mujoco.MjSpec,
    name: str,
    joint_name: str,
    entry: ActuatorDeclaration,
    velocities: Mapping[str, float],
) -> dict[str, tuple[str, ValueOrigin]]:
    """Add the actuator ``entry`` declares on ``joint_name``; returns each value it set, as text, and
    where the value came from (gains and gear from the spec, ranges from the spec or the joint)."""
    joint = spec.joint(joint_name)
    actuator = spec.add_actuator(name=name, target=joint_name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    _configure(actuator, entry)
    values: dict[str, tuple[str, ValueOrigin]] = {}
    for gain in GAIN_FIELDS:
        value = getattr(entry, gain)
        if value is not None:
            values[gain] = (str(value) if isinstance(value, list) else f"{value:g}", "spec")
    if entry.gear != 1:
        values["gear"] = (f"{entry.gear:g}", "spec")
    for attribute, (value, origin) in _ranges(spec, joint, entry, velocities).items():
        setattr(actuator, attribute, list(value) if value is not None else [0.0, 0.0])
        setattr(actuator, attribute.replace("range", "limited"), TRUE if value is not None else FALSE)
        values[attribute] = (range_text(value), origin)
    return values


@dataclass(frozen=True)
class MotorActuation:
    """What the actuator of a motor-driven joint is, in numbers at the joint."""

    control: str
    """voltage, torque or position."""

    gear_ratio: float
    efficiency: float
    force_limit: float | None = None
    """The largest joint torque (N·m); None: unlimited."""

    voltage: float | None = None
    torque_constant: float | None = None
    resistance: float | None = None
    voltage_actuator: str = "dcmotor"
    """dcmotor or general (control: voltage)."""

    kp: float | None = None
    kv: float | None = None
    dampratio: float | None = None


def _limit(actuator: mujoco.MjsActuator, attribute: str, value: Range | None) -> None:
    setattr(actuator, attribute, list(value) if value is not None else [0.0, 0.0])
    setattr(actuator, attribute.replace("range", "limited"), TRUE if value is not None else FALSE)


def add_motor_actuator(
    spec: mujoco.MjSpec, name: str, joint_name: str, drive: MotorActuation
) -> dict[str, str]:
    """Add the actuator ``drive`` describes on ``joint_name``; returns what it set, as text."""
    actuator = spec.add_actuator(name=name, target=joint_name, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    limit = (-drive.force_limit, drive.force_limit) if drive.force_limit is not None else None
    values: dict[str, str] = {}
    if drive.control == "voltage":
        kt, resistance, voltage = drive.torque_constant, drive.resistance, drive.voltage
        assert kt is not None and resistance is not None and voltage is not None  # checked by the caller
        n, eta = drive.gear_ratio, drive.efficiency
        if drive.voltage_actuator == "dcmotor":
            actuator.set_to_dcmotor(motorconst=[kt, kt], resistance=resistance / eta)
            actuator.gear = [n, 0, 0, 0, 0, 0]
            values["motorconst"] = f"[{kt:.6g}, {kt:.6g}]"
            values["resistance"] = f"{resistance / eta:.6g}"
            values["gear"] = f"{n:.6g}"
        else:
            gain, slope = n * eta * kt / resistance, -(n**2) * eta * kt**2 / resistance
            actuator.gaintype = mujoco.mjtGain.mjGAIN_FIXED
            actuator.gainprm = [gain, *[0.0] * 9]
            actuator.biastype = mujoco.mjtBias.mjBIAS_AFFINE
            actuator.biasprm = [0.0, 0.0, slope, *[0.0] * 7]
            values["gainprm"] = f"[{gain:.6g}]"
            values["biasprm"] = f"[0, 0, {slope:.6g}]"
        _limit(actuator, "ctrlrange", (-voltage, voltage))
        values["ctrlrange"] = range_text((-voltage, voltage))
        _limit(actuator, "forcerange", None)
        return values
    if drive.control == "position":
        kv = drive.kv if drive.kv is not None else -1.0
        dampratio = drive.dampratio if drive.dampratio is not None else -1.0
        actuator.set_to_position(kp=drive.kp or 0.0, kv=kv, dampratio=dampratio)
        for field in ("kp", "kv", "dampratio"):
            gain = getattr(drive, field)
            if gain is not None:
                values[field] = f"{gain:.6g}"
        ctrl = _joint_range(spec, spec.joint(joint_name))
    else:
        actuator.set_to_motor()
        ctrl = limit
    _limit(actuator, "ctrlrange", ctrl)
    values["ctrlrange"] = range_text(ctrl)
    _limit(actuator, "forcerange", limit)
    values["forcerange"] = range_text(limit)
    return values
