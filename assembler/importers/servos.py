"""The actuators ``assembler new`` adds where the file has none for a joint: position servos whose
stiffness reaches the joint's effort limit near the target, critically damped, stable at the model's
timestep, so that the robot holds the pose it is given."""

from __future__ import annotations

from typing import Any

import mujoco

from assembler.importers.entries import Entry
from assembler.importers.entries import short as _short
from assembler.importers.physics import joint_id, posed_data, torque_limit
from assembler.importers.reading import ModelFile
from assembler.models.motor_table import MOTORS


def actuated_joints(model: mujoco.MjModel) -> dict[str, int]:
    """Joint name -> the actuator driving it, for actuators with a joint transmission."""
    driven = {}
    for actuator in range(model.nu):
        if int(model.actuator_trntype[actuator]) == int(mujoco.mjtTrn.mjTRN_JOINT):
            name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, int(model.actuator_trnid[actuator, 0]))
            driven[name or ""] = actuator
    return driven


def actuator_label(model: mujoco.MjModel, actuator: int) -> str:
    """The actuator's name, or for an unnamed one the joint it drives (``the servo of joint waist``)."""
    name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, actuator)
    if name:
        return str(name)
    joint = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, int(model.actuator_trnid[actuator, 0]))
    return f"of joint {joint}"


def driven_joints(model: mujoco.MjModel, joints: tuple[str, ...]) -> list[str]:
    """The joints that need a motor of their own: all but those a joint equality makes follow another
    (a URDF's ``<mimic>``; ``actuators:`` globs skip them too)."""
    followers = {
        mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, int(model.eq_obj1id[e]))
        for e in range(model.neq)
        if int(model.eq_type[e]) == int(mujoco.mjtEq.mjEQ_JOINT)
    }
    return [name for name in joints if name not in followers]


SATURATION = 0.05
"""rad (or m): the position error at which a servo ``new`` adds reaches its joint's effort limit, so its
stiffness is the limit over this (a load within the limit leaves an error below it)."""

DAMPING_RATIO = 1.0
"""The servos' damping as a ratio of critical damping at the home pose (MuJoCo's ``dampratio``)."""


STABLE = 0.5
"""The largest natural frequency of a servo ``new`` adds, times the model's timestep: a stiffer servo on
a light joint (the SO-101's) would make MuJoCo's explicit step blow up."""


def _servo_gain(limit: float, inertia: float, timestep: float) -> tuple[float, bool]:
    """The stiffness of a servo that reaches ``limit`` at :data:`SATURATION`, at most what keeps its
    natural frequency (with the joint's inertia at home) below :data:`STABLE` / timestep; to three
    digits, and whether it was capped."""
    gain, cap = limit / SATURATION, inertia * (STABLE / timestep) ** 2
    return float(f"{min(gain, cap):.3g}"), cap < gain


def actuator_entry(file: ModelFile, joints: tuple[str, ...]) -> Entry | None:
    """Position servos for the joints no actuator of the file drives (every joint of a URDF; metaworld's
    Sawyer drives only its claws, its arm follows a mocap weld), so the robot holds the pose it is given: each
    joint's stiffness reaches the joint's effort limit (its force range) at :data:`SATURATION`, its
    damping critical; a guessed limit (twice gravity's load) where the file gives none."""
    actuated = set(actuated_joints(file.model))
    if len(actuated) < file.model.nu:  # tendons or sites drive some joints (the Shadow hand's couplings)
        return None
    driven = [name for name in driven_joints(file.model, joints) if name not in actuated]
    if not driven:
        return None
    data = posed_data(file.model)
    limits = {name: torque_limit(file.model, data, name) for name in driven}
    declared: list[dict[str, Any]] = []
    capped = []
    for name, limit in limits.items():
        dof = int(file.model.jnt_dofadr[joint_id(file.model, name)])
        gain, cut = _servo_gain(limit.value, float(file.model.dof_M0[dof]), float(file.model.opt.timestep))
        capped += [name] if cut else []
        servo: dict[str, Any] = {"match": name, "kp": gain, "dampratio": DAMPING_RATIO}
        if not limit.from_file:
            servo["forcerange"] = [-limit.value, limit.value]
        declared.append(servo)
    which = (
        f"the {file.format.upper()} has no actuators"
        if not actuated
        else f"no actuator drives {_short(driven)}"
    )
    entry = Entry("actuators", declared).guess(
        f"{which}: a position servo per joint, so the robot holds the pose it is given; kp reaches the "
        f"joint's effort limit (its force range) {SATURATION} rad from the target, damping critical "
        f"(dampratio {DAMPING_RATIO:g})"
    )
    if capped:
        entry.guess(
            f"{_short(capped)}: kp lowered so that the servo stays stable at the model's timestep "
            f"(natural frequency {STABLE} / timestep with the joint's inertia at home)"
        )
    followers = [n for n in joints if n not in driven_joints(file.model, joints)]
    if followers:
        entry.guess(f"{_short(followers)} follow another joint (URDF <mimic>): no servo")
    guessed = [name for name, limit in limits.items() if not limit.from_file]
    if guessed:
        entry.decide(
            f"no effort limit in the file for {_short(guessed)}: their forcerange is a guess, twice the "
            "torque gravity can load each joint with (arm stretched out); set each joint's torque limit "
            "from the datasheet"
        )
    motors = _shipped_motors({name: limit.value for name, limit in limits.items() if limit.from_file})
    if motors:
        entry.decide(
            f"the file's effort limits are those of shipped motors ({motors}): a motors: entry per joint, "
            "e.g. {match: JOINT, motor: NAME, control: position}, gives each joint its motor's armature and "
            "limit instead of these servos (docs/motors.md); check that the robot has these motors"
        )
    return entry


def _shipped_motors(efforts: dict[str, float]) -> str:
    """Joints whose effort limit is a shipped motor's torque limit, grouped by the motors, as text
    (``FL_hip_joint, FR_hip_joint: UnitreeGo1HipMotor or UnitreeGo2HipMotor; ...``); "" if none."""
    groups: dict[tuple[str, ...], list[str]] = {}
    for joint, effort in efforts.items():
        names = tuple(MOTORS.limited_to(effort))
        if names:
            groups.setdefault(names, []).append(joint)
    return "; ".join(f"{_short(joints, 4)}: {' or '.join(names)}" for names, joints in groups.items())
