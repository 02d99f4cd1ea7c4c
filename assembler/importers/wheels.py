"""What ``assembler new`` writes for a wheeled robot without an arm (a racecar, a rover, a Husky): a
mobile base spec (``kind: base``, ``type: mobile``) an arm is put on, its footprint and heights read
off the model's geometry, velocity servos on its wheels and position servos on its other joints."""

from __future__ import annotations

import re
from typing import Any

import mujoco
import numpy as np

from assembler.importers.decisions import balance_entry, file_joint_values, init_qpos_entry
from assembler.importers.entries import Entry, short
from assembler.importers.physics import joint_id, posed_data, torque_limit
from assembler.importers.reading import ModelFile
from assembler.importers.servos import STABLE, actuator_entry
from assembler.importers.tree import Tree
from assembler.tools.render.stage import box_corners

SPIN_SATURATION = 1.0
"""rad/s: the wheel speed error at which a wheel's velocity servo reaches its effort limit."""

STEERING = re.compile(r"steer", re.IGNORECASE)
"""A hinge that turns a wheel's axis (a position servo), not the wheel itself (racecar's right steering
hinge is a URDF ``continuous`` joint: unlimited, and still a steering hinge)."""


def is_wheeled_base(tree: Tree) -> bool:
    """True for a robot with wheels and neither arm nor feet: a mobile base, not a robot of its own."""
    return bool(tree.wheels) and tree.limbs is None and not tree.arm


def _footprint(model: mujoco.MjModel, root: int) -> tuple[float, float, float]:
    """Heights of the lowest point of all geoms and of the root body's top, and the largest
    horizontal distance of a geom from the root, relative to the root at the home pose (collision
    geoms where the model has any, as the floor meets them)."""
    data = posed_data(model)
    colliding = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
    geoms = colliding or list(range(model.ngeom))
    everything = box_corners(model, data, geoms) - data.xpos[root]
    own = [g for g in geoms if int(model.geom_bodyid[g]) == root] or geoms
    top = box_corners(model, data, own) - data.xpos[root]
    radius = float(np.max(np.linalg.norm(everything[:, :2], axis=1)))
    return float(everything[:, 2].min()), float(top[:, 2].max()), radius


def _rounded(value: float) -> float:
    return round(value, 3) + 0.0  # no -0.0 in the spec


def _wheel_servos(file: ModelFile, wheels: tuple[str, ...]) -> list[dict[str, Any]]:
    """A velocity servo per wheel: ``kv`` reaches the wheel's effort limit at :data:`SPIN_SATURATION`,
    lowered to what MuJoCo's explicit step keeps stable with the wheel's inertia."""
    model, data = file.model, posed_data(file.model)
    servos = []
    for name in wheels:
        limit = torque_limit(model, data, name)
        inertia = float(model.dof_M0[int(model.jnt_dofadr[joint_id(model, name)])])
        kv = float(f"{min(limit.value / SPIN_SATURATION, inertia * STABLE / float(model.opt.timestep)):.3g}")
        servo: dict[str, Any] = {"match": name, "type": "velocity", "kv": kv}
        if not limit.from_file:
            servo["forcerange"] = [-limit.value, limit.value]
        servos.append(servo)
    return servos


def base_entries(file: ModelFile, tree: Tree) -> list[Entry]:
    """The fields of a wheeled base's spec after its kind, name and file."""
    model = file.model
    root = next(b for b in range(1, model.nbody) if model.body_parentid[b] == 0)
    root_name = model.body(root).name
    bottom, top, radius = _footprint(model, root)
    entries = [
        *balance_entry(file),
        Entry("type", "mobile").guess(
            f"wheels ({short(tree.wheels, 4)}) and no arm: a mobile base an arm is put on "
            "(default_base: in the arm's spec); a robot of its own: assembler new --kind robot"
        ),
        Entry("support_body", root_name).guess("the root body, the chassis: the arm is attached to it"),
        Entry("top_offset", [0.0, 0.0, _rounded(top)]).guess(
            "from the root to the top of its own geoms, where an arm stands"
        ),
        Entry("bottom_offset", [0.0, 0.0, _rounded(bottom)]).guess(
            "from the root to the lowest point of the wheels: robosuite puts this point on the floor"
        ),
        Entry("horizontal_radius", _rounded(radius)).guess(
            "the farthest geom from the root, seen from above"
        ),
    ]
    others = [name for name in tree.joints if name not in tree.wheels]
    groups: dict[str, list[str]] = {"base": list(tree.wheels)}
    if tree.head:
        groups["head"] = list(tree.head)
    joints = Entry("joint_groups", groups).guess("base: the wheels and their steering")
    unplaced = [name for name in others if name not in tree.head]
    if unplaced:
        joints.decide(f"{short(unplaced, 4)} belong to no group of a base; list them where they belong")
    entries.append(joints)
    pose = init_qpos_entry(file, tree.joints)
    entries += [pose] if pose else []
    entries.append(file_joint_values())
    entries += _actuators(file, tree, others)
    entries.append(
        Entry("add_free_joint", False).decide(
            "a URDF cannot say how its base moves: welded, it stays where it is put and spins its wheels "
            "(robosuite moves its own mobile bases by joints a controller drives); true lets it roll on "
            "its wheels"
        )
    )
    return entries


def _actuators(file: ModelFile, tree: Tree, others: list[str]) -> list[Entry]:
    """Velocity servos on the wheels, position servos on the other joints, where the file drives none."""
    steered = [
        name
        for name in tree.wheels
        if STEERING.search(name) or file.model.jnt_limited[joint_id(file.model, name)]
    ]
    spinning = tuple(name for name in tree.wheels if name not in steered)
    positions = actuator_entry(file, (*steered, *others))
    if positions is None and file.model.nu:
        return []  # the file drives its joints itself
    declared: list[dict[str, Any]] = list(positions.value) if positions else []
    entry = positions or Entry("actuators", [])
    entry.value = [*_wheel_servos(file, spinning), *declared]
    if spinning:
        entry.guess(
            f"{short(spinning, 4)}: a velocity servo per wheel (ctrl in rad/s); kv reaches the wheel's "
            f"effort limit {SPIN_SATURATION} rad/s from the target speed"
        )
    return [entry] if entry.value else []


__all__ = ["base_entries", "is_wheeled_base"]
