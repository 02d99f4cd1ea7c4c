"""Numbers ``assembler new`` reads off the compiled model: a home pose inside every joint's range,
the bodies that overlap there, and a torque (or force) limit per joint for the motors it adds to a file
without actuators.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

GRAVITY = 9.81
"""m/s^2; the limit guessed for a joint is twice what gravity can load it with (:func:`torque_limit`)."""

SAFETY = 2.0
"""How many times the worst static gravity load a guessed limit allows (an arm must also accelerate)."""

FLOOR = 1.0
"""The smallest guessed limit, in N m or N: a finger's static load alone would not move it."""

SCALAR = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
"""Joint types holding one value, as integers: on MuJoCo 4 an array item is not ``in`` a tuple of enums."""


@dataclass(frozen=True)
class Limit:
    """A joint's torque or force limit and where it came from."""

    value: float
    from_file: bool


def joint_id(model: mujoco.MjModel, name: str) -> int:
    """The joint's index in the compiled model."""
    return int(mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_JOINT, name))


def scalar_joints(model: mujoco.MjModel, names: Sequence[str]) -> bool:
    """Whether every named joint holds one value (hinge or slide), so init_qpos can list them."""
    return all(int(model.jnt_type[joint_id(model, name)]) in SCALAR for name in names)


def home_pose(model: mujoco.MjModel, names: Sequence[str]) -> tuple[list[float], list[str]]:
    """MuJoCo's qpos0 per joint, with every value outside its joint's range moved to the middle of the
    range; and the names of the joints moved."""
    pose, moved = [], []
    for name in names:
        joint = joint_id(model, name)
        value = float(model.qpos0[model.jnt_qposadr[joint]])
        low, high = (float(v) for v in model.jnt_range[joint])
        if model.jnt_limited[joint] and not low <= value <= high:
            value = (low + high) / 2
            moved.append(name)
        pose.append(round(value, 6))
    return pose, moved


def _subtree_bodies(model: mujoco.MjModel, top: int) -> list[int]:
    bodies = []
    for body in range(1, model.nbody):
        walk = body
        while walk > 0 and walk != top:
            walk = int(model.body_parentid[walk])
        if walk == top:
            bodies.append(body)
    return bodies


def round_up(value: float) -> float:
    """Up to two significant digits (a guess should not look more precise than it is)."""
    if value <= 0:
        return value
    scale = 10 ** (math.floor(math.log10(value)) - 1)
    return float(round(math.ceil(value / scale) * scale, 10))


def torque_limit(model: mujoco.MjModel, data: mujoco.MjData, name: str) -> Limit:
    """The file's effort limit (URDF ``effort``, MJCF ``actuatorfrcrange``), else a guess: twice the
    largest static load gravity can put on the joint (its subtree's masses at their distances from
    the joint, as if stretched out), at least :data:`FLOOR`."""
    joint = joint_id(model, name)
    if model.jnt_actfrclimited[joint]:
        low, high = (float(v) for v in model.jnt_actfrcrange[joint])
        if high > low:
            return Limit(max(abs(low), abs(high)), True)
    bodies = _subtree_bodies(model, int(model.jnt_bodyid[joint]))
    masses = model.body_mass[bodies]
    if int(model.jnt_type[joint]) == int(mujoco.mjtJoint.mjJNT_SLIDE):
        load = float(masses.sum())
    else:
        distances = np.linalg.norm(data.xipos[bodies] - data.xanchor[joint], axis=1)
        load = float(masses @ distances)
    return Limit(max(FLOOR, round_up(SAFETY * GRAVITY * load)), False)


def posed_data(model: mujoco.MjModel) -> mujoco.MjData:
    """The model's data at qpos0, positions computed."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    return data


OVERLAP = 0.002
"""m: the deepest overlap of two of the robot's geoms at its home pose said as a problem."""


def overlaps(
    model: mujoco.MjModel, joints: tuple[str, ...], pose: list[float]
) -> list[tuple[str, str, float]]:
    """The pairs of bodies whose geoms overlap by more than :data:`OVERLAP` at ``pose`` (values of
    ``joints``, the rest at qpos0), each once with its deepest overlap in m, deepest first."""
    data = mujoco.MjData(model)
    for name, value in zip(joints, pose, strict=True):
        data.qpos[model.jnt_qposadr[joint_id(model, name)]] = value
    mujoco.mj_forward(model, data)
    deepest: dict[tuple[str, str], float] = {}
    for contact in (data.contact[i] for i in range(data.ncon)):
        if contact.dist < -OVERLAP:
            first, second = (
                model.body(int(model.geom_bodyid[g])).name for g in (contact.geom1, contact.geom2)
            )
            deepest[first, second] = max(deepest.get((first, second), 0.0), -float(contact.dist))
    return sorted(((*pair, depth) for pair, depth in deepest.items()), key=lambda item: -item[2])
