"""What ``assembler new`` writes for a robot arm or a hand: each field guessed from the compiled model
(:mod:`~assembler.importers.tree`, :mod:`~assembler.importers.physics`) with the reason beside it,
and what the file cannot tell marked with the field to set."""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

from assembler.importers.entries import Entry
from assembler.importers.physics import home_pose, joint_id, posed_data, scalar_joints, torque_limit
from assembler.importers.reading import ModelFile
from assembler.importers.tree import FINGER_BODY_WORDS, Tree
from assembler.models.motor_table import MOTORS
from assembler.robosuite.conventions import has_force_range, is_bridge_servo
from assembler.tools.lint.gripper_pose import ROOT_OFFSET_LIMIT

DEFAULT_GRIPPER = "PincerGripper"
"""The shipped two-finger gripper an arm without a jaw of its own gets, so robosuite's tasks can grasp."""

STAND_IN_BASE = "Pedestal"
"""The base robosuite stands an arm on (a floor-standing arm cannot reach robosuite's tables)."""

NO_RULES = {"frictionloss": None, "damping": None, "armature": None}


def _short(names: tuple[str, ...] | list[str], limit: int = 6) -> str:
    shown = ", ".join(names[:limit])
    return shown + (f" and {len(names) - limit} more" if len(names) > limit else "")


def _actuated_joints(model: mujoco.MjModel) -> dict[str, int]:
    """Joint name -> the actuator driving it, for actuators with a joint transmission."""
    driven = {}
    for actuator in range(model.nu):
        if int(model.actuator_trntype[actuator]) == int(mujoco.mjtTrn.mjTRN_JOINT):
            name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_JOINT, int(model.actuator_trnid[actuator, 0]))
            driven[name or ""] = actuator
    return driven


def _actuator_label(model: mujoco.MjModel, actuator: int) -> str:
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
    actuated = set(_actuated_joints(file.model))
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


OVERLAP = 0.002
"""m: the deepest overlap of two of the robot's geoms at its home pose said as a problem."""


def _overlap(model: mujoco.MjModel, joints: tuple[str, ...], pose: list[float]) -> str:
    """The deepest overlap of two geoms at ``pose`` beyond :data:`OVERLAP`, as words; "" if none."""
    data = mujoco.MjData(model)
    for name, value in zip(joints, pose, strict=True):
        data.qpos[model.jnt_qposadr[joint_id(model, name)]] = value
    mujoco.mj_forward(model, data)
    contacts = [data.contact[i] for i in range(data.ncon) if data.contact[i].dist < -OVERLAP]
    if not contacts:
        return ""
    deepest = min(contacts, key=lambda contact: contact.dist)
    bodies = [model.body(int(model.geom_bodyid[g])).name for g in (deepest.geom1, deepest.geom2)]
    return f"the bodies {bodies[0]} and {bodies[1]} overlap by {-deepest.dist * 1000:.0f} mm"


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


def robosuite_entry(file: ModelFile, arm: tuple[str, ...], servos_added: bool = False) -> Entry:
    """How the arm enters robosuite: standing on a pedestal, its position servos made motors."""
    model, options, entry = file.model, {"stand_in_base": STAND_IN_BASE}, Entry("robosuite", {})
    servos = [a for name, a in _actuated_joints(model).items() if name in arm and is_bridge_servo(model, a)]
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
        bare = [_actuator_label(model, a) for a in servos]
        bare = [name for name, a in zip(bare, servos, strict=True) if not has_force_range(model, a)]
        if bare:
            entry.decide(f"give the servos {_short(bare)} a forcerange in the model (actuators: in the spec)")
    if "right_center" not in {model.site(s).name for s in range(model.nsite)}:
        entry.guess(
            "the file has no site right_center, the arm's origin robosuite's controllers read: robosuite's "
            "bridge adds one on the body the arm's first link hangs from (lint RA704)"
        )
    entry.guess(
        f"robosuite stands the arm on the {STAND_IN_BASE} (without one it would stand on the floor, "
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


def robot_entries(file: ModelFile, tree: Tree) -> list[Entry]:
    """The fields of an arm's spec after its name and file."""
    entries = balance_entry(file)
    entries.append(
        Entry("morphology", "manipulator").guess(
            f"one arm of {len(tree.arm)} joints; a bimanual robot needs arm_type: bimanual and a left arm "
            "in joint_groups, a humanoid morphology: humanoid"
        )
    )
    if tree.eef_by_name:
        how = "the body named like a hand below the last arm joint"
    else:
        how = "the body where the fingers branch off" if tree.fingers else "the last link of the arm's chain"
    eef = Entry("eef_bodies", {"right": tree.eef_body}).guess(f"{how}; grippers are mounted here")
    if tree.grip_site:
        eef.guess(f"the file's grip frame is the site {tree.grip_site}")
    entries.append(eef)
    groups: dict[str, list[str]] = {"right": list(tree.arm)}
    for part in ("base", "torso", "head"):
        if getattr(tree, part):
            groups[part] = list(getattr(tree, part))
    joints = Entry("joint_groups", groups).guess(
        "the arm is the chain of joints from the root to the deepest link"
        + "".join(
            f"; {part}: {_short(list(getattr(tree, part)))}"
            for part in ("base", "torso", "head")
            if getattr(tree, part)
        )
    )
    if tree.fingers:
        joints.decide(
            f"{_short(tree.fingers)} move a jaw or fingers that are part of this file: they are listed in no "
            "group, so that robosuite's arm controller does not drive them; list them under right: if it "
            "should"
        )
    entries.append(joints)
    fixed_hand = _fixed_fingers(file.model, tree.eef_body)
    if tree.fingers:
        entries.append(
            Entry("default_grippers", {"right": None}).guess(
                "the file has its own jaw, so no gripper is added; a gripper spec of the jaw needs its "
                "own file"
            )
        )
    elif fixed_hand:
        entries.append(
            Entry("default_grippers", {"right": None}).decide(
                f"the file has its own hand, fixed ({_short(fixed_hand, 3)}: bodies named like fingers "
                "below the end effector, without joints): no gripper is added on top of it; a gripper "
                "of your choice needs a file of the arm without that hand"
            )
        )
    else:
        entries.append(
            Entry("default_grippers", {"right": DEFAULT_GRIPPER}).guess(
                f"no jaw in the file: the shipped {DEFAULT_GRIPPER}, so robosuite's tasks can grasp; any "
                "registered gripper (assembler list grippers) or null"
            )
        )
    pose = init_qpos_entry(file, tree.joints)
    entries += [pose] if pose else []
    entries.append(
        Entry("joint_defaults", dict(NO_RULES)).guess(
            "the file's own frictionloss, damping and armature are kept; delete this line for robosuite's "
            "rules (0.1, 0.1 and 5/(i+1) where the file sets none)"
        )
    )
    actuators = actuator_entry(file, tree.joints)
    entries += [actuators] if actuators else []
    entries.append(robosuite_entry(file, tree.arm, servos_added=actuators is not None))
    return entries


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
