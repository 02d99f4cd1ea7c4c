"""A jaw inside an arm's own file (pybullet's and example-robot-data's Panda, Fetch) made the robot's
gripper: the arm's spec cuts the hand from the arm (``remove_bodies``) and names a
gripper spec that takes the hand from the same file (``root_body``), so robosuite gives the jaw an
action as it gives any gripper one. A hand that turns on one of the arm's joints (SO-101's
``gripper_link`` on ``wrist_roll``) cannot be cut without that joint, and a jaw driven by actuators
without names cannot be given actions: their jaws stay in the arm. (``new`` names the file's unnamed
actuators on joints before, :mod:`~assembler.importers.actuator_fixes`: metaworld's Sawyer's claws
are cut.)"""

from __future__ import annotations

from typing import Any

import mujoco

from assembler.importers.decisions import Jaw, balance_entry, file_joint_values, init_qpos_entry
from assembler.importers.entries import Entry, short
from assembler.importers.reading import ModelFile
from assembler.importers.servos import actuated_joints, actuator_entry, actuator_label
from assembler.importers.tree import SLIDE, Tree, subtree


def jaw_of(model: mujoco.MjModel, tree: Tree, name: str) -> Jaw | None:
    """The jaw of an arm's file that can be cut from the arm, as the gripper ``name``; None for a legged
    or bimanual robot (``new`` writes one jaw's gripper spec, not one per arm), a file without fingers, a
    hand that turns on a joint of its own (cutting it would cut an arm joint), or a jaw whose actuators
    in the file have no names (its actions could not name them)."""
    if tree.limbs is not None or tree.arms or not tree.fingers or not tree.eef_body:
        return None
    hand = model.body(tree.eef_body).id
    parent = int(model.body_parentid[hand])
    if model.body_jntnum[hand] or parent == 0:
        return None
    below = set(subtree(model, hand))
    joints = tuple(model.joint(j).name for j in range(model.njnt) if int(model.jnt_bodyid[j]) in below)
    if set(joints) != set(tree.fingers):
        return None
    driven = actuated_joints(model)
    if any(not model.actuator(driven[j]).name for j in joints if j in driven):
        return None  # a gripper's actions name its actuators: one new could not name (actuator_fixes)
    return Jaw(name, tree.eef_body, model.body(parent).name, joints)


def jaw_entries(file: ModelFile, jaw: Jaw, tree: Tree) -> list[Entry]:
    """The fields of the jaw's gripper spec after its kind, name, description and file."""
    entries = [
        *balance_entry(file),
        Entry("root_body", jaw.hand).guess(
            f"the body where the fingers ({short(jaw.joints, 3)}) branch off, with everything below it; the "
            "arm's spec cuts it from the arm (remove_bodies)"
        ),
        Entry("eef_body", jaw.hand).guess(
            "the hand; set the body at the grip point if there is one (robosuite adds an eef body here)"
        ),
    ]
    if tree.grip_site:
        entries.append(
            Entry("important_sites", {"grip_site": tree.grip_site}).guess(
                f"the site {tree.grip_site} is named like a grip point"
            )
        )
    pose = init_qpos_entry(file, jaw.joints)
    entries += [pose] if pose else []
    entries.append(file_joint_values())
    servos = actuator_entry(file, jaw.joints)
    entries += [servos] if servos else []
    entries.append(_actions(file, jaw, servos))
    return entries


def _actions(file: ModelFile, jaw: Jaw, servos: Entry | None) -> Entry:
    """One action dimension opening and closing the jaw as one, +1 closing (robosuite's convention)."""
    model = file.model
    names = [actuator_label(model, a) for joint, a in actuated_joints(model).items() if joint in jaw.joints]
    names += [str(servo["match"]) for servo in servos.value] if servos else []
    dimension: dict[str, Any] = {"actuators": names}
    slides = all(int(model.jnt_type[model.joint(name).id]) == SLIDE for name in jaw.joints)
    entry = Entry("actions", {"mode": "absolute", "dimensions": [dimension]})
    if slides:
        dimension["direction"] = [-1] * len(names)
        entry.guess(
            "one dimension for the whole jaw, +1 closing as robosuite's grippers close: sliding fingers "
            "close towards the low end of their range"
        )
    else:
        entry.guess("one dimension for the whole jaw, the action's value each actuator's place in its range")
    return entry.decide(
        "check in assembler render (or robosuite) that +1 closes the jaw; direction: [-1] turns it round"
    )


__all__ = ["jaw_entries", "jaw_of"]
