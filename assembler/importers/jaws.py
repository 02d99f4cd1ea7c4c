"""A jaw inside an arm's own file (pybullet's and example-robot-data's Panda, Fetch) made the robot's
gripper: the arm's spec cuts the hand from the arm (``remove_bodies``) and names a
gripper spec that takes the hand from the same file (``root_body``), so robosuite gives the jaw an
action as it gives any gripper one. A hand that turns on one of the arm's joints (SO-101's
``gripper_link`` on ``wrist_roll``) cannot be cut without that joint, and a jaw driven by actuators
without names cannot be given actions: their jaws stay in the arm. (``new`` names the file's unnamed
actuators on joints before, :mod:`~assembler.importers.actuator_fixes`: metaworld's Sawyer's claws
are cut.) A bimanual robot's hands (example-robot-data's Baxter) are cut each on its own, into a
gripper spec per hand (:func:`jaws_of`): each keeps the file's own bodies and names, so the built robot
is the file's, where one spec used on both arms would put a copy of one hand on the other arm."""

from __future__ import annotations

from typing import Any

import mujoco

from assembler.importers.decisions import Jaw, balance_entry, file_joint_values, init_qpos_entry
from assembler.importers.entries import Entry, short
from assembler.importers.physics import home_pose, overlaps
from assembler.importers.reading import ModelFile
from assembler.importers.servos import actuated_joints, actuator_entry, actuator_label
from assembler.importers.tree import SLIDE, Tree, subtree


def jaw_of(model: mujoco.MjModel, tree: Tree, name: str) -> Jaw | None:
    """The jaw of a one-arm file that can be cut from the arm, as the gripper ``name``; None for a legged
    or bimanual robot (:func:`jaws_of` cuts a bimanual robot's hands), a file without fingers, or a hand
    :func:`_cut` cannot cut."""
    if tree.limbs is not None or tree.arms:
        return None
    return _cut(model, tree.eef_body, tree.fingers, name)


def jaws_of(model: mujoco.MjModel, tree: Tree, names: dict[str, str]) -> dict[str, Jaw]:
    """The hands of a bimanual robot's file that can be cut from their arms, by side, each as the
    gripper ``names[side]``; a side whose hand :func:`_cut` cannot cut (or without one) is left out."""
    cut = {side: _cut(model, arm.eef_body, arm.fingers, names[side]) for side, arm in tree.arms.items()}
    return {side: jaw for side, jaw in cut.items() if jaw is not None}


def _cut(model: mujoco.MjModel, hand_body: str, fingers: tuple[str, ...], name: str) -> Jaw | None:
    """The hand ``hand_body``, where ``fingers`` branch off, cut from its arm as the gripper ``name``; None
    without fingers, for a hand that turns on a joint of its own (cutting it would cut an arm joint) or
    hangs from the world, when joints other than ``fingers`` lie below it, or for a jaw whose actuators
    in the file have no names (its actions could not name them)."""
    if not fingers or not hand_body:
        return None
    hand = model.body(hand_body).id
    parent = int(model.body_parentid[hand])
    if model.body_jntnum[hand] or parent == 0:
        return None
    below = set(subtree(model, hand))
    joints = tuple(model.joint(j).name for j in range(model.njnt) if int(model.jnt_bodyid[j]) in below)
    if set(joints) != set(fingers):
        return None
    driven = actuated_joints(model)
    if any(not model.actuator(driven[j]).name for j in joints if j in driven):
        return None  # a gripper's actions name its actuators: one new could not name (actuator_fixes)
    return Jaw(name, hand_body, model.body(parent).name, joints)


def jaw_entries(file: ModelFile, jaw: Jaw, grip_site: str | None) -> list[Entry]:
    """The fields of the jaw's gripper spec after its kind, name, description and file; ``grip_site``:
    a site below the hand named like a grip point, if any."""
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
    if grip_site:
        entries.append(
            Entry("important_sites", {"grip_site": grip_site}).guess(
                f"the site {grip_site} is named like a grip point"
            )
        )
    pose = init_qpos_entry(file, jaw.joints)
    entries += [pose] if pose else []
    entries.append(file_joint_values())
    excludes = _fingers_apart(file, jaw)
    entries += [excludes] if excludes else []
    servos = actuator_entry(file, jaw.joints)
    entries += [servos] if servos else []
    entries.append(_actions(file, jaw, servos))
    return entries


def _fingers_apart(file: ModelFile, jaw: Jaw) -> Entry | None:
    """``contact_excludes`` for the pairs of the hand's own bodies that overlap at its home pose
    (example-robot-data's Baxter: each finger's long collision box lies 5 mm inside the other finger's
    base box): MuJoCo collides any two bodies but a parent and its child, and such a pair slides in
    contact over the whole travel, its friction holding the jaw near where it starts."""
    model = file.model
    hand = set(subtree(model, model.body(jaw.hand).id))
    names = {model.body(b).name for b in hand}
    pose, _ = home_pose(model, jaw.joints)
    pairs = [(a, b, depth) for a, b, depth in overlaps(model, jaw.joints, pose) if {a, b} <= names]
    if not pairs:
        return None
    said = ", ".join(f"{a} and {b} by {depth * 1000:.0f} mm" for a, b, depth in pairs)
    return Entry("contact_excludes", [[a, b] for a, b, _ in pairs]).guess(
        f"the hand's own bodies overlap at its home pose ({said}): MuJoCo would collide them as the jaw "
        "moves, and the contact jams it; delete a pair if its bodies should touch"
    )


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


__all__ = ["jaw_entries", "jaw_of", "jaws_of"]
