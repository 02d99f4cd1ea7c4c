"""What ``assembler new`` writes for a robot with feet (:mod:`~assembler.importers.limbs`): a legged
robot without arms (``morphology: legged``), a humanoid (two arms), or a legged manipulator (one arm);
floating on its own feet, no gripper guessed onto any limb."""

from __future__ import annotations

from assembler.importers.decisions import balance_entry, file_joint_values, init_qpos_entry
from assembler.importers.entries import Entry, short
from assembler.importers.reading import ModelFile
from assembler.importers.servos import actuator_entry
from assembler.importers.tree import FREE, Tree


def _morphology(tree: Tree) -> tuple[Entry, list[str]]:
    assert tree.limbs is not None
    arms = [side for side in ("right", "left") if tree.limbs.arms.get(side)]
    feet = (
        f"{len(tree.limbs.feet)} feet ({short(tree.limbs.feet, 4)}): leaf bodies well below the root, each "
        "at the end of a leg"
    )
    if not arms:
        return Entry("morphology", "legged").guess(f"{feet}, and no joint that is no leg's: no arms"), arms
    if len(arms) == 2:
        how = "by their names" if tree.limbs.sides_by_name else "by the side of the robot each lies on"
        entry = Entry("morphology", "humanoid").guess(f"{feet}; two arms, told right and left {how}")
        return entry, arms
    return Entry("morphology", "legged_manipulator").guess(f"{feet}; one arm"), arms


def _free_joint(file: ModelFile) -> list[Entry]:
    model = file.model
    if any(int(model.jnt_type[j]) == FREE for j in range(model.njnt)):
        return []
    root = next(b for b in range(1, model.nbody) if model.body_parentid[b] == 0)
    if model.body_jntnum[root]:
        return []
    what = "a URDF cannot declare one" if file.format == "urdf" else "the file gives its root none"
    return [
        Entry("add_free_joint", True).guess(
            f"a legged robot stands on its own feet: its root gets a free joint ({what}); false welds it"
        )
    ]


MJLAB_LIMIT_FACTOR = 0.9
"""The share of each joint's range mjlab's limit terms allow, as mjlab's own Go1 and G1 configure it."""


def _mjlab_entry(file: ModelFile) -> Entry:
    """What mjlab's velocity task reads of a legged robot: an IMU, the feet (the spec's ``feet``), the
    soft joint-limit factor (:mod:`assembler.mjlab` makes the sites and sensors from them)."""
    model = file.model
    root = next(b for b in range(1, model.nbody) if model.body_parentid[b] == 0)
    return (
        Entry("mjlab", {"imu_body": model.body(root).name, "soft_joint_pos_limit_factor": MJLAB_LIMIT_FACTOR})
        .guess(
            "what mjlab's tasks read: an IMU on the root body (its gyro, velocimeter and angular momentum "
            f"sensors), the feet above with a contact sensor over them, {MJLAB_LIMIT_FACTOR} of each joint's "
            "range allowed as mjlab's Go1 and G1 allow"
        )
        .decide("set imu_pos to where the robot's IMU sits in that body (metres)")
    )


def legged_entries(file: ModelFile, tree: Tree) -> list[Entry]:
    """The fields of a legged robot's spec after its name and file."""
    limbs = tree.limbs
    assert limbs is not None
    morphology, arms = _morphology(tree)
    entries = [*balance_entry(file), morphology]
    if len(arms) == 2:
        entries.append(Entry("arm_type", "bimanual").guess("a humanoid has two arms"))
    entries += _free_joint(file)
    entries.append(
        Entry("feet", list(limbs.feet)).guess("the bodies the robot stands on: the ends of its legs")
    )
    if arms:
        entries.append(
            Entry("eef_bodies", {side: limbs.hands[side] for side in arms}).guess(
                "the body at the end of each arm, where its branches (fingers) meet"
            )
        )
    groups: dict[str, list[str]] = {"legs": list(limbs.legs)}
    for part in ("torso", "head", "base"):
        if getattr(tree, part):
            groups[part] = list(getattr(tree, part))
    for side in arms:
        groups[side] = list(limbs.arms[side])
    joints = Entry("joint_groups", groups).guess(
        "legs: the joints on the way to one foot; torso: what moves several limbs at once (a waist, a "
        "spine); head: joints named head or neck" + ("; arms: the other joints, by side" if arms else "")
    )
    if tree.fingers:
        joints.decide(
            f"{short(tree.fingers, 4)} move fingers or a jaw of this file: in no group, so that no arm "
            "controller drives them; list them under their arm's side if it should"
        )
    entries.append(joints)
    if arms:
        has_hands = (
            "the file's hands (fingers or jaws) are its own" if tree.fingers else "no gripper is guessed"
        )
        entries.append(
            Entry("default_grippers", dict.fromkeys(arms)).guess(
                f"{has_hands}: no gripper is added to an arm of a legged robot; any registered gripper "
                "(assembler list grippers)"
            )
        )
    pose = init_qpos_entry(file, tree.joints)
    if pose is not None:
        pose.decide(
            "a legged robot stands on a floor: check that this pose stands (assembler render) and that "
            "its feet reach the floor from the root's height in the file"
        )
        entries.append(pose)
    entries.append(file_joint_values())
    actuators = actuator_entry(file, tree.joints)
    entries += [actuators] if actuators else []
    entries.append(_mjlab_entry(file))
    if arms:
        entries.append(
            Entry("robosuite", {"enabled": False}).decide(
                "robosuite's legged robots stand on a legged base its tasks were made for; true to try it "
                "in robosuite's environments"
            )
        )
    return entries


__all__ = ["legged_entries"]
