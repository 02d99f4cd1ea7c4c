"""What ``assembler new`` writes for a hand or gripper after its kind, name and file: its root as the
end effector, where its fingers point (and the mount that turns them out of an arm's flange), a grip
site, its home pose, servos where it has no actuators, one action per actuator."""

from __future__ import annotations

import mujoco
import numpy as np

from assembler.importers.decisions import balance_entry, init_qpos_entry
from assembler.importers.entries import Entry
from assembler.importers.physics import posed_data
from assembler.importers.reading import ModelFile
from assembler.importers.servos import actuator_entry
from assembler.importers.tree import Tree
from assembler.tools.lint.gripper_pose import ROOT_OFFSET_LIMIT


def root_pose_entry(file: ModelFile, root: str) -> Entry | None:
    """``root_pose: reset`` for a hand whose file places its root far from the origin (in a scene),
    where it would float away from the arm it is mounted on (lint RA102)."""
    distance = float(np.linalg.norm(posed_data(file.model).xpos[file.model.body(root).id]))
    if distance <= ROOT_OFFSET_LIMIT:
        return None
    return Entry("root_pose", "reset").guess(
        f"the file places the root body {root} {distance:.3g} m from the origin (its place in a scene), "
        f"more than a mount offset ({ROOT_OFFSET_LIMIT} m): reset puts it at the hand it is mounted on"
    )


AXES = ("+x", "-x", "+y", "-y", "+z", "-z")

TO_Z: dict[str, list[float]] = {
    "+x": [0.707107, 0.0, -0.707107, 0.0],
    "-x": [0.707107, 0.0, 0.707107, 0.0],
    "+y": [0.707107, 0.707107, 0.0, 0.0],
    "-y": [0.707107, -0.707107, 0.0, 0.0],
    "-z": [0.0, 1.0, 0.0, 0.0],
}
"""The rotation (w, x, y, z) that turns each axis of the hand's root into +z, where robosuite's grippers
point."""


def _pointing(model: mujoco.MjModel, root: str) -> str:
    """The axis of the root body's frame the hand's fingertips lie along (the leaf bodies' mean)."""
    data = posed_data(model)
    top = model.body(root).id
    parents = set(int(p) for p in model.body_parentid)
    leaves = []
    for body in range(top + 1, model.nbody):
        walk = body
        while walk > top:
            walk = int(model.body_parentid[walk])
        if walk == top and body not in parents:
            leaves.append(body)
    if not leaves:
        return "+z"
    rotation = data.xmat[top].reshape(3, 3)
    reach = rotation.T @ (data.xpos[leaves].mean(axis=0) - data.xpos[top])
    axis = int(np.argmax(np.abs(reach)))
    return AXES[2 * axis + (0 if reach[axis] >= 0 else 1)]


def mount_note(file: ModelFile, root: str) -> str | None:
    """What to write on the arm when the hand's fingers do not point along +z of its root."""
    axis = _pointing(file.model, root)
    if axis == "+z":
        return None
    return (
        f"the fingers reach along {axis} of the root body {root}, robosuite's grippers along +z of the "
        f"hand: on the arm's spec, gripper_mount: {{right: {{quat: {TO_Z[axis]}}}}} turns it to point out "
        "of the flange (then check the closing direction in assembler render)"
    )


def gripper_entries(file: ModelFile, tree: Tree) -> list[Entry]:
    """The fields of a hand's spec after its kind, name and file."""
    entries = [
        *balance_entry(file),
        Entry("eef_body", tree.eef_body).guess(
            "the root body; set the body at the grip point if there is one (robosuite adds an eef body here)"
        ),
    ]
    mount = mount_note(file, tree.eef_body)
    if mount:
        entries[-1].decide(mount)
    pose_of_root = root_pose_entry(file, tree.eef_body)
    entries += [pose_of_root] if pose_of_root else []
    sites = Entry("important_sites", {"grip_site": tree.grip_site} if tree.grip_site else {})
    if tree.grip_site:
        sites.guess(f"the site {tree.grip_site} is named like a grip point")
    else:
        sites.decide("no grip site in the file (robosuite adds grip_site at eef_body); name one if it has it")
    entries.append(sites)
    entries.append(
        Entry("important_sensors", {}).guess(
            "no force/torque sensors named force_ee, torque_ee in the file (robosuite adds them)"
        )
    )
    pose = init_qpos_entry(file, tree.joints)
    entries += [pose] if pose else []
    actuators = actuator_entry(file, tree.joints)
    entries += [actuators] if actuators else []
    names = [
        mujoco.mj_id2name(file.model, mujoco.mjtObj.mjOBJ_ACTUATOR, a) or "" for a in range(file.model.nu)
    ]
    if actuators is not None:  # the servos new adds, named after their joints
        names += [str(servo["match"]) for servo in actuators.value]
    if names:
        entries.append(
            Entry(
                "actions", {"mode": "absolute", "dimensions": [{"actuators": [name]} for name in names]}
            ).decide(
                "one action per actuator, its value the actuator's position in its range (robosuite's "
                "dexterous hands); a jaw that opens and closes as one: one dimension with every actuator"
            )
        )
    return entries
