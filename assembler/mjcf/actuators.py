"""One declared actuator (a spec's ``actuators:`` entry) added to a joint of a part's MjSpec.

Ranges the entry leaves out come from the joint: a position servo's ``ctrlrange`` is the joint's
range, a velocity servo's the URDF's velocity limit, a motor's the joint's effort limit divided by
the gear; ``forcerange`` is the joint's effort limit. Each range comes back with where it came from,
for ``assembler inspect``. Which joints an entry drives is decided in
:mod:`assembler.models.actuator_table`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
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
