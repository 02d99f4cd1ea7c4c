"""What ``assembler new`` writes for a robot arm: each field guessed from the compiled model
(:mod:`~assembler.importers.tree`, :mod:`~assembler.importers.physics`) with the reason beside it,
and what the file cannot tell marked with the field to set."""

from __future__ import annotations

from dataclasses import dataclass

import mujoco

from assembler.importers.entries import Entry
from assembler.importers.entries import short as _short
from assembler.importers.physics import home_pose, overlaps, scalar_joints
from assembler.importers.reading import ModelFile
from assembler.importers.servos import actuated_joints, actuator_entry, actuator_label
from assembler.importers.tree import FINGER_BODY_WORDS, Tree
from assembler.robosuite.conventions import has_force_range, is_bridge_servo

DEFAULT_GRIPPER = "PincerGripper"
"""The shipped two-finger gripper an arm without a jaw of its own gets, so robosuite's tasks can grasp."""

STAND_IN_BASE = "Pedestal"
"""The base robosuite stands an arm on (a floor-standing arm cannot reach robosuite's tables)."""

NO_RULES = {"frictionloss": None, "damping": None, "armature": None}


def _overlap(model: mujoco.MjModel, joints: tuple[str, ...], pose: list[float]) -> str:
    """The deepest overlap of two geoms at ``pose`` beyond :data:`OVERLAP`, as words; "" if none."""
    found = overlaps(model, joints, pose)
    if not found:
        return ""
    first, second, depth = found[0]
    return f"the bodies {first} and {second} overlap by {depth * 1000:.0f} mm"


def init_qpos_entry(file: ModelFile, joints: tuple[str, ...]) -> Entry | None:
    """The home pose: MuJoCo's qpos0, moved inside any joint range it lies outside."""
    if not joints or not scalar_joints(file.model, joints):
        return None
    pose, moved = home_pose(file.model, joints)
    entry = Entry("init_qpos", pose).guess("the file's zero pose (MuJoCo's qpos0), one value per joint")
    if moved:
        entry.guess(f"{_short(moved)} moved to the middle of their range: qpos0 lies outside it")
    overlap = _overlap(file.model, joints, pose)
    if overlap:
        entry.decide(
            f"at this pose {overlap}: MuJoCo pushes them apart from the first step; set a pose where "
            "they clear"
        )
    return entry.decide("set init_qpos to the pose the robot should start each episode in")


def robosuite_entry(
    file: ModelFile, arm: tuple[str, ...], servos_added: bool = False, arms: tuple[str, ...] = ("right",)
) -> Entry:
    """How the robot enters robosuite: standing on a pedestal, its position servos made motors; ``arm``:
    the joints of its ``arms``."""
    model, options, entry = file.model, {"stand_in_base": STAND_IN_BASE}, Entry("robosuite", {})
    servos = [a for name, a in actuated_joints(model).items() if name in arm and is_bridge_servo(model, a)]
    if servos_added:
        options["actuation"] = "torque"
        entry.guess(
            "robosuite's controllers write torques: in robosuite each servo above becomes a motor whose "
            "ctrlrange is its forcerange; as_is keeps the servos"
        )
    elif servos:
        options["actuation"] = "torque"
        entry.guess(
            "the arm's actuators are position servos: in robosuite each becomes a motor whose ctrlrange "
            "is its forcerange (robosuite's controllers write torques); as_is keeps the servos"
        )
        bare = [actuator_label(model, a) for a in servos]
        bare = [name for name, a in zip(bare, servos, strict=True) if not has_force_range(model, a)]
        if bare:
            entry.decide(f"give the servos {_short(bare)} a forcerange in the model (actuators: in the spec)")
    sites = {model.site(s).name for s in range(model.nsite)}
    missing = [f"{side}_center" for side in arms if f"{side}_center" not in sites]
    if len(arms) == 1 and missing:
        entry.guess(
            "the file has no site right_center, the arm's origin robosuite's controllers read: robosuite's "
            "bridge adds one on the body the arm's first link hangs from (lint RA704)"
        )
    elif missing:
        entry.guess(
            f"the file has no site {' or '.join(missing)}, the arms' origins robosuite's controllers read: "
            "robosuite's bridge adds each on the body its arm's first link hangs from (lint RA704)"
        )
    what = "arm" if len(arms) == 1 else "robot"
    entry.guess(
        f"robosuite stands the {what} on the {STAND_IN_BASE} (without one it would stand on the floor, "
        "below robosuite's tables); set default_base to build it on a base everywhere"
    )
    entry.value = options
    return entry


def balance_entry(file: ModelFile) -> list[Entry]:
    """``balance_inertia: true`` when MuJoCo refused the URDF's inertias until balanced, with one line
    per link changed, its inertia before and after."""
    if not file.balance_inertia:
        return []
    entry = Entry("balance_inertia", True).guess(
        "MuJoCo refuses this URDF's inertias: each such link's inertia is made isotropic at the mean of "
        "its principal moments; correct the URDF's <inertial> instead (new --strict refuses the file)"
    )
    for note in file.source.notes:
        if note.startswith("balance_inertia: "):
            entry.guess(note.removeprefix("balance_inertia: "))
    return [entry]


def _fixed_fingers(model: mujoco.MjModel, eef: str) -> list[str]:
    """Bodies below ``eef`` named like fingers (Kinova j2s6s200's URDF welds its two fingers on)."""
    top = model.body(eef).id
    names = []
    for body in range(top + 1, model.nbody):
        walk = body
        while walk > top:
            walk = int(model.body_parentid[walk])
        name = model.body(body).name
        if walk == top and FINGER_BODY_WORDS.search(name):
            names.append(name)
    return names


def file_joint_values() -> Entry:
    """``joint_defaults`` without rules: the file's own frictionloss, damping and armature are kept."""
    return Entry("joint_defaults", dict(NO_RULES)).guess(
        "the file's own frictionloss, damping and armature are kept; delete this line for robosuite's "
        "rules (0.1, 0.1 and 5/(i+1) where the file sets none)"
    )


def robot_entries(file: ModelFile, tree: Tree, jaws: dict[str, Jaw] | None = None) -> list[Entry]:
    """The fields of an arm's (or a bimanual robot's) spec after its name and file; ``jaws``: by arm,
    the file's hand cut from that arm and made the gripper of its name (:mod:`~assembler.importers.jaws`)."""
    jaws = jaws or {}
    entries = balance_entry(file)
    entries += _two_arms(file, tree, jaws) if tree.arms else _one_arm(file, tree, jaws.get("right"))
    cut = {name for jaw in jaws.values() for name in jaw.joints}
    own = tuple(name for name in tree.joints if name not in cut)  # a jaw's joints go with it
    pose = init_qpos_entry(file, own)
    entries += [pose] if pose else []
    entries.append(file_joint_values())
    actuators = actuator_entry(file, own)
    entries += [actuators] if actuators else []
    entries.append(
        robosuite_entry(file, tree.arm_joints, actuators is not None, tuple(tree.arms) or ("right",))
    )
    return entries


def _one_arm(file: ModelFile, tree: Tree, jaw: Jaw | None) -> list[Entry]:
    """Morphology, end effector, joint groups and gripper of a robot with one arm."""
    entries = [
        Entry("morphology", "manipulator").guess(
            f"one arm of {len(tree.arm)} joints; a bimanual robot needs arm_type: bimanual and a left arm "
            "in joint_groups, a humanoid morphology: humanoid"
        )
    ]
    entries += _end_effector(tree) if jaw is None else _cut_hand(jaw)
    parts, said = _parts(tree)
    joints = Entry("joint_groups", {"right": list(tree.arm), **parts}).guess(
        f"the arm is the chain of joints from the root to the deepest link{said}"
    )
    if tree.fingers and jaw is None:
        joints.decide(
            f"{_short(tree.fingers)} move a jaw or fingers that are part of this file: they are listed in no "
            "group, so that robosuite's arm controller does not drive them; list them under right: if it "
            "should"
        )
    entries.append(joints)
    entries.append(_default_gripper(file, tree, jaw))
    return entries


def _parts(tree: Tree) -> tuple[dict[str, list[str]], str]:
    """The joint groups besides the arms (base, torso, head) and what they hold, as words."""
    groups = {part: list(getattr(tree, part)) for part in ("base", "torso", "head") if getattr(tree, part)}
    return groups, "".join(f"; {part}: {_short(joints)}" for part, joints in groups.items())


def _two_arms(file: ModelFile, tree: Tree, jaws: dict[str, Jaw]) -> list[Entry]:
    """Morphology, end effectors, joint groups and grippers of a robot with two arms on one root body
    (:func:`~assembler.importers.tree.read_tree`): Baxter, YuMi, a bimanual torso; ``jaws``: the hands
    cut from their arms, by side."""
    right, left = tree.arms["right"], tree.arms["left"]
    how = "by their joints' names" if tree.arms_by_name else "by the side of the root each lies on (+y: left)"
    entries = [
        Entry("morphology", "manipulator").guess(
            f"two arms on one root body, of {len(right.joints)} and {len(left.joints)} joints, told right "
            f"and left {how}; a humanoid (standing on legs of its own) is morphology: humanoid"
        ),
        Entry("arm_type", "bimanual").guess(
            "a right and a left arm, driven as one robot (robosuite's Baxter)"
        ),
    ]
    eef = Entry(
        "eef_bodies",
        {side: jaws[side].mount if side in jaws else arm.eef_body for side, arm in tree.arms.items()},
    )
    hows = {
        side: "the body its hand (cut below, the gripper) hangs from"
        if side in jaws
        else _eef_how(arm.eef_by_name, bool(arm.fingers))
        for side, arm in tree.arms.items()
    }
    if hows["right"] == hows["left"]:
        eef.guess(f"on each arm {hows['right']}; grippers are mounted here")
    else:
        eef.guess(f"right: {hows['right']}; left: {hows['left']}; grippers are mounted here")
    for side, arm in tree.arms.items():
        if arm.grip_site:
            eef.guess(f"the {side} arm's grip frame is the site {arm.grip_site}")
    entries.append(eef)
    if jaws:
        said = "; ".join(f"{side}: {_short(jaw.joints, 3)}" for side, jaw in jaws.items())
        names = " and ".join(jaw.name for jaw in jaws.values())
        grippers = (
            f"the grippers {names}, whose specs" if len(jaws) == 2 else f"the gripper {names}, whose spec"
        )
        entries.append(
            Entry("remove_bodies", [jaw.hand for jaw in jaws.values()]).guess(
                f"each hand and its jaw ({said}) are cut from its arm and made {grippers} (beside this "
                "one) take them from the same file, so robosuite gives each jaw an action"
            )
        )
    parts, said = _parts(tree)
    joints = Entry("joint_groups", {"right": list(right.joints), "left": list(left.joints), **parts}).guess(
        f"each arm is its side's chain of joints from the root to its deepest link{said}"
    )
    cut = {name for jaw in jaws.values() for name in jaw.joints}
    kept = [name for name in tree.fingers if name not in cut]
    if kept:
        joints.decide(
            f"{_short(kept)} move the hands that are part of this file: they are listed in no group, "
            "so that robosuite's arm controllers do not drive them; list each hand's under its arm's side "
            "if it should"
        )
    entries.append(joints)
    entries.append(_two_grippers(file, tree, jaws))
    return entries


def _two_grippers(file: ModelFile, tree: Tree, jaws: dict[str, Jaw]) -> Entry:
    """Each arm's gripper: its hand cut from the file (``jaws``), none on a hand of the file's own that
    could not be cut, else the shipped gripper."""
    hands = {side: arm.fingers for side, arm in tree.arms.items() if arm.fingers and side not in jaws}
    fixed = {side: _fixed_fingers(file.model, arm.eef_body) for side, arm in tree.arms.items()}
    grippers: dict[str, str | None] = {
        side: jaws[side].name if side in jaws else None if side in hands or fixed[side] else DEFAULT_GRIPPER
        for side in tree.arms
    }
    entry = Entry("default_grippers", grippers)
    if jaws:
        entry.guess(
            f"the file's own {'hands' if len(jaws) == 2 else 'hand'}, each the gripper of its arm; any "
            "registered gripper (assembler list grippers) in a hand's place"
        )
    if hands:
        said = "; ".join(f"{side}: {_short(joints, 3)}" for side, joints in hands.items())
        roots = ", ".join(tree.arms[side].eef_body for side in hands)
        entry.decide(
            f"{'each hand is' if len(hands) == 2 else 'the hand is'} the file's own ({said}): no gripper is "
            "added on top of it, and its fingers stay in the arm without a robosuite action: new cuts a hand "
            "into a gripper only where it is welded to its arm (no joint of its own), holds no joint but its "
            f"fingers, and its actuators have names ({roots}: docs/add-your-robot.md)"
        )
    for side, names in fixed.items():
        if names and side not in hands and side not in jaws:
            entry.decide(
                f"the {side} arm has its own hand, fixed ({_short(names, 3)}: bodies named like fingers "
                "below the end effector, without joints): no gripper is added on top of it"
            )
    bare = [side for side, gripper in grippers.items() if gripper == DEFAULT_GRIPPER]
    if bare:
        where = "either arm" if len(bare) == 2 else f"the {bare[0]} arm"
        entry.guess(
            f"no jaw on {where} in the file: the shipped {DEFAULT_GRIPPER}, so robosuite's tasks can grasp; "
            "any registered gripper (assembler list grippers) or null"
        )
    return entry


def _eef_how(by_name: bool, fingers: bool) -> str:
    """How an end-effector body was found (:func:`~assembler.importers.tree.read_tree`), as words."""
    if by_name:
        return "the body named like a hand below the last arm joint"
    return "the body where the fingers branch off" if fingers else "the last link of the arm's chain"


def _end_effector(tree: Tree) -> list[Entry]:
    how = _eef_how(tree.eef_by_name, bool(tree.fingers))
    eef = Entry("eef_bodies", {"right": tree.eef_body}).guess(f"{how}; grippers are mounted here")
    if tree.grip_site:
        eef.guess(f"the file's grip frame is the site {tree.grip_site}")
    return [eef]


def _cut_hand(jaw: Jaw) -> list[Entry]:
    """The end effector and the cut of an arm whose file's hand is the gripper ``jaw.name``."""
    return [
        Entry("eef_bodies", {"right": jaw.mount}).guess(
            f"the body the hand {jaw.hand} hangs from; the hand is the gripper mounted here"
        ),
        Entry("remove_bodies", [jaw.hand]).guess(
            f"the hand and its jaw ({_short(jaw.joints, 3)}) are cut from the arm and made the gripper "
            f"{jaw.name}, whose spec (beside this one) takes them from the same file, so robosuite gives "
            "the jaw an action"
        ),
    ]


def _default_gripper(file: ModelFile, tree: Tree, jaw: Jaw | None) -> Entry:
    if jaw is not None:
        return Entry("default_grippers", {"right": jaw.name}).guess(
            "the file's own jaw; any registered gripper (assembler list grippers) in its place"
        )
    if tree.fingers:
        return Entry("default_grippers", {"right": None}).guess(
            "the file has its own jaw, so no gripper is added; a gripper spec of the jaw needs its own file"
        )
    fixed_hand = _fixed_fingers(file.model, tree.eef_body)
    if fixed_hand:
        return Entry("default_grippers", {"right": None}).decide(
            f"the file has its own hand, fixed ({_short(fixed_hand, 3)}: bodies named like fingers "
            "below the end effector, without joints): no gripper is added on top of it; a gripper "
            "of your choice needs a file of the arm without that hand"
        )
    return Entry("default_grippers", {"right": DEFAULT_GRIPPER}).guess(
        f"no jaw in the file: the shipped {DEFAULT_GRIPPER}, so robosuite's tasks can grasp; any "
        "registered gripper (assembler list grippers) or null"
    )


@dataclass(frozen=True)
class Jaw:
    """The hand of an arm's file that becomes a gripper spec of its own (:mod:`~assembler.importers.jaws`)."""

    name: str
    """The gripper spec's name."""
    hand: str
    """The body cut from the arm, the gripper's root: where the fingers branch off."""
    mount: str
    """The hand's parent, the arm's end effector the gripper is mounted on."""
    joints: tuple[str, ...]
    """The jaw's joints: every joint below the hand."""
