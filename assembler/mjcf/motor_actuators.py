"""A motor's actuator on one joint of a part's MjSpec, from numbers already derived at the joint.

- voltage, ``dcmotor``: MuJoCo's DC motor with ``gear = N``, ``motorconst = (kt, kt)`` (in SI units
  the back-EMF constant equals the torque constant) and ``resistance = R / η``: MuJoCo's model has no
  gearbox efficiency, and ``N·kt/(R/η)·(V − kt·N·ω)`` is exactly ``N·η·kt·(V − kt·N·ω)/R``;
- voltage, ``general``: the same law as a ``general`` actuator, ``gain = N·η·kt/R`` and an affine
  velocity bias ``−N²·η·kt²/R`` (what its basic form computes, for engines without ``dcmotor``);
- torque: a motor whose ctrl is the joint torque, within ±limit;
- position: a position servo whose force is limited to ±limit.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco

from assembler.mjcf.actuators import FALSE, TRUE, Range, _joint_range, range_text


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
