"""What the kinematic tree of a compiled model says about a robot: which joints are fingers, which
move the whole robot, the arm's chain (or two arms' on one root body), the end-effector body and a
grip frame. Every answer is a
guess from names and structure; :mod:`assembler.importers.decisions` says why beside it.
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field

import mujoco

from assembler.importers.limbs import Limbs, read_limbs, serial_chain, two_arms

FINGER_WORDS = re.compile(r"finger|gripper|jaw|claw|knuckle|thumb|grip", re.IGNORECASE)
"""Joint names of a jaw or fingers (robosuite's grippers and most vendors' files name them so)."""

EEF_WORDS = re.compile(
    r"(^|[_/:.])(right_hand|left_hand|hand|eef|ee_link|ee|tool0|tool|flange|tcp|attachment)$",
    re.IGNORECASE,
)
"""Body names vendors give the end of an arm, where a gripper is mounted."""

FINGER_BODY_WORDS = re.compile(r"finger|jaw|claw|knuckle|thumb", re.IGNORECASE)
"""Body names of a jaw's or hand's moving parts (metaworld's Sawyer: joint r_close on body rightclaw); not
``gripper``, a word vendors also give the wrist link (the ViperX's gripper_link turns on wrist_rotate)."""

GRIP_WORDS = re.compile(r"grip|pinch|tcp|eef|ee_site", re.IGNORECASE)
"""Site names vendors give a grip point."""

WHEEL_WORDS = re.compile(r"wheel|caster|castor|tire|tyre|steer", re.IGNORECASE)
"""Names of a wheeled robot's wheels and of the hinges steering them (racecar's
``left_steering_hinge_joint``), on the joint or the body it turns."""

PART_WORDS: dict[str, re.Pattern[str]] = {
    "torso": re.compile(r"torso", re.IGNORECASE),
    "head": re.compile(r"head|neck", re.IGNORECASE),
}
"""Body-part groups recognized by joint name (robosuite's own name rules; a neck is a head's)."""

FREE = int(mujoco.mjtJoint.mjJNT_FREE)
"""As an integer: on MuJoCo 4 enums compare unreliably with the items of model arrays."""

HINGE = int(mujoco.mjtJoint.mjJNT_HINGE)
SLIDE = int(mujoco.mjtJoint.mjJNT_SLIDE)


@dataclass(frozen=True)
class ArmChain:
    """One arm of a bimanual robot, by MJCF name."""

    joints: tuple[str, ...]
    fingers: tuple[str, ...]
    """Its hand's joints: those named like fingers below the arm, and every joint below where they
    branch off."""
    eef_body: str
    """Where its hand's fingers branch off, else a body named like a hand below it, else its last link."""
    eef_by_name: bool
    grip_site: str | None
    """A site below the end effector named like a grip point, if any."""


@dataclass(frozen=True)
class Tree:
    """The kinematic tree's guesses, by MJCF name (joints in MuJoCo's order)."""

    joints: tuple[str, ...]
    arm: tuple[str, ...]
    fingers: tuple[str, ...]
    base: tuple[str, ...]
    torso: tuple[str, ...]
    head: tuple[str, ...]
    eef_body: str
    eef_by_name: bool
    """True when the end-effector body was found by its name, False when it is the last arm link."""
    grip_site: str | None
    limbs: Limbs | None = None
    """A legged robot's feet, legs and arms (then ``arm`` is its right arm, if any); None for a robot
    without feet (an arm, a wheeled base)."""
    wheels: tuple[str, ...] = ()
    """Wheels and the hinges steering them (also in ``base``: they move the whole robot)."""
    arms: dict[str, ArmChain] = field(default_factory=dict)
    """A fixed-base robot's ``right`` and ``left`` arm when it has two (then ``arm``, ``eef_body``,
    ``eef_by_name`` and ``grip_site`` are its right arm's, ``fingers`` both hands'); empty otherwise."""
    arms_by_name: bool = False
    """True when the two arms' sides come from their joints' names, False from where they lie."""

    @property
    def arm_joints(self) -> tuple[str, ...]:
        """Every arm joint: both arms' of a bimanual robot, else the one arm's."""
        return tuple(n for arm in self.arms.values() for n in arm.joints) if self.arms else self.arm


def _name(model: mujoco.MjModel, kind: mujoco.mjtObj, index: int) -> str:
    return mujoco.mj_id2name(model, kind, index) or ""


def _ancestors(model: mujoco.MjModel, body: int) -> list[int]:
    """``body`` and its ancestors up to (not including) the world, deepest first."""
    chain = []
    while body > 0:
        chain.append(body)
        body = int(model.body_parentid[body])
    return chain


def _joint_count(model: mujoco.MjModel, body: int, skip: frozenset[int] = frozenset()) -> int:
    """The joints between the world and ``body``, but those in ``skip``."""
    chain = set(_ancestors(model, body))
    return sum(1 for j in range(model.njnt) if int(model.jnt_bodyid[j]) in chain and j not in skip)


def _wheel_joints(model: mujoco.MjModel, joints: list[int]) -> list[int]:
    """Hinges named like a wheel or its steering, or turning a body named so."""
    return [
        j
        for j in joints
        if int(model.jnt_type[j]) == HINGE
        and (
            WHEEL_WORDS.search(_name(model, mujoco.mjtObj.mjOBJ_JOINT, j))
            or WHEEL_WORDS.search(_name(model, mujoco.mjtObj.mjOBJ_BODY, int(model.jnt_bodyid[j])))
        )
    ]


def _common_ancestor(model: mujoco.MjModel, bodies: list[int]) -> int:
    shared = set(_ancestors(model, bodies[0]))
    for body in bodies[1:]:
        shared &= set(_ancestors(model, body))
    return max(shared, key=lambda b: len(_ancestors(model, b))) if shared else 1


def subtree(model: mujoco.MjModel, top: int) -> list[int]:
    """``top`` and every body below it."""
    return [b for b in range(1, model.nbody) if top in _ancestors(model, b)]


def _named_fingers(model: mujoco.MjModel, joints: list[int]) -> list[int]:
    """Joints named like fingers, or moving a body named so."""
    return [
        j
        for j in joints
        if FINGER_WORDS.search(_name(model, mujoco.mjtObj.mjOBJ_JOINT, j))
        or FINGER_BODY_WORDS.search(_name(model, mujoco.mjtObj.mjOBJ_BODY, int(model.jnt_bodyid[j])))
    ]


def _finger_joints(model: mujoco.MjModel, joints: list[int], named: list[int] | None = None) -> list[int]:
    """``named`` (by default the joints named like fingers, or moving a body named so), and every joint
    below the first body such a joint hangs from: one hand."""
    if named is None:
        named = _named_fingers(model, joints)
    if not named:
        return []
    hand = _common_ancestor(model, [int(model.body_parentid[model.jnt_bodyid[j]]) for j in named])
    below = set(subtree(model, hand)) - {hand}
    return [j for j in joints if j in named or int(model.jnt_bodyid[j]) in below]


def _eef_body(model: mujoco.MjModel, arm: list[int], fingers: list[int]) -> tuple[int, bool]:
    """The body a gripper goes on: where the fingers branch off, else a body named like a hand below
    the last arm joint, else the last arm joint's body."""
    if fingers:
        return _common_ancestor(
            model, [int(model.body_parentid[model.jnt_bodyid[j]]) for j in fingers]
        ), False
    if not arm:
        return 1, False
    last = int(model.jnt_bodyid[arm[-1]])
    for body in subtree(model, last):
        if EEF_WORDS.search(_name(model, mujoco.mjtObj.mjOBJ_BODY, body)):
            return body, True
    return last, False


def _grip_site(model: mujoco.MjModel, top: int) -> str | None:
    below = set(subtree(model, top))
    for site in range(model.nsite):
        name = _name(model, mujoco.mjtObj.mjOBJ_SITE, site)
        if int(model.site_bodyid[site]) in below and GRIP_WORDS.search(name):
            return name
    return None


def read_tree(model: mujoco.MjModel, hand: bool) -> Tree:
    """The guesses for ``model``: a robot's arm and parts, or (``hand``) a gripper's grip frame."""
    joints = [j for j in range(model.njnt) if int(model.jnt_type[j]) != FREE]
    names = {j: _name(model, mujoco.mjtObj.mjOBJ_JOINT, j) for j in joints}
    roots = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    if hand:  # the world child holding the most joints (a scene file also has a floor, a table...)
        root = max(roots, key=lambda top: sum(int(model.body_jntnum[b]) for b in subtree(model, top)))
        site = _grip_site(model, root)
        every = tuple(names.values())
        return Tree(every, (), every, (), (), (), _name(model, mujoco.mjtObj.mjOBJ_BODY, root), False, site)
    base = [j for j in joints if int(model.jnt_bodyid[j]) in roots]
    legged = _legged_tree(model, joints, names, roots, base)
    if legged is not None:
        return legged
    wheels = [j for j in _wheel_joints(model, joints) if j not in base]
    base += wheels  # wheels move the whole robot, as a mobile base's joints do
    bimanual = _two_arm_tree(model, joints, names, roots, base, wheels)
    if bimanual is not None:
        return bimanual
    fingers = _finger_joints(model, [j for j in joints if j not in base])
    parts = {
        part: [j for j in joints if j not in base and j not in fingers and words.search(names[j])]
        for part, words in PART_WORDS.items()
    }
    taken = {*base, *fingers, *parts["torso"], *parts["head"]}
    deepest = max(range(1, model.nbody), key=lambda b: (_joint_count(model, b, frozenset(wheels)), -b))
    on_chain = set(_ancestors(model, deepest))
    arm = [j for j in joints if j not in taken and int(model.jnt_bodyid[j]) in on_chain]
    others = [j for j in joints if j not in taken and j not in arm]
    arm += others  # joints on side branches (none in a serial arm) stay with the arm, and are said
    eef, by_name = _eef_body(model, [j for j in arm if j not in others] or arm, fingers)
    return Tree(
        joints=tuple(names.values()),
        arm=tuple(names[j] for j in arm),
        fingers=tuple(names[j] for j in fingers),
        base=tuple(names[j] for j in base),
        torso=tuple(names[j] for j in parts["torso"]),
        head=tuple(names[j] for j in parts["head"]),
        eef_body=_name(model, mujoco.mjtObj.mjOBJ_BODY, eef),
        eef_by_name=by_name,
        grip_site=_grip_site(model, eef),
        wheels=tuple(names[j] for j in wheels),
    )


def _legged_tree(
    model: mujoco.MjModel, joints: list[int], names: dict[int, str], roots: list[int], base: list[int]
) -> Tree | None:
    """The tree of a robot with feet (:mod:`~assembler.importers.limbs`), or None. Fingers are the
    joints named so (each hand's own: no subtree of both hands is taken for a jaw)."""
    root = max(roots, key=lambda top: (sum(int(model.body_jntnum[b]) for b in subtree(model, top)), -top))
    fingers = [j for j in joints if FINGER_WORDS.search(names[j])]
    head = [j for j in joints if j not in fingers and PART_WORDS["head"].search(names[j])]
    limbs = read_limbs(model, root, skip={*base, *fingers, *head})
    if limbs is None:
        return None
    told = {*limbs.legs, *(n for arm in limbs.arms.values() for n in arm)}
    told |= {names[j] for j in (*base, *fingers, *head)}
    torso = [names[j] for j in joints if names[j] not in told]  # a waist, a spine, what no limb holds
    eef = limbs.hands.get("right")
    return Tree(
        joints=tuple(names.values()),
        arm=limbs.arms.get("right", ()),
        fingers=tuple(names[j] for j in fingers),
        base=tuple(names[j] for j in base),
        torso=tuple(torso),
        head=tuple(names[j] for j in head),
        eef_body=eef or "",
        eef_by_name=False,
        grip_site=_grip_site(model, model.body(eef).id) if eef else None,
        limbs=limbs,
    )


def _two_arm_tree(
    model: mujoco.MjModel,
    joints: list[int],
    names: dict[int, str],
    roots: list[int],
    base: list[int],
    wheels: list[int],
) -> Tree | None:
    """The tree of a robot without feet with two arms under its root body
    (:func:`~assembler.importers.limbs.two_arms`), or None; ``base``: the joints moving the whole robot
    (``wheels`` among them). Each arm's hand is the fingers below it (never one hand over both arms);
    what moves and is no arm, hand, head or base moves both arms: the torso. A floating robot (a free
    joint) whose feet were not found is left to the one-arm guess, which says how many joints it took."""
    if any(int(model.jnt_type[j]) == FREE for j in range(model.njnt)):
        return None
    root = max(roots, key=lambda top: (sum(int(model.body_jntnum[b]) for b in subtree(model, top)), -top))
    named = _named_fingers(model, [j for j in joints if j not in base])
    parts = {
        part: [j for j in joints if j not in base and j not in named and words.search(names[j])]
        for part, words in PART_WORDS.items()
    }
    found = two_arms(model, root, skip={*base, *named, *parts["torso"], *parts["head"]})
    if found is None:
        return None
    sides, by_name = found
    arms: dict[str, ArmChain] = {}
    fingers: set[int] = set()
    for side in ("right", "left"):
        bodies = {int(model.jnt_bodyid[j]) for j in sides[side]}
        own = [j for j in named if bodies & set(_ancestors(model, int(model.jnt_bodyid[j])))]
        hand = _finger_joints(model, [j for j in joints if j not in base], own) if own else []
        arm = [j for j in sides[side] if j not in hand]
        eef, eef_by_name = _eef_body(model, serial_chain(model, arm), hand)
        fingers |= {*hand, *own}
        arms[side] = ArmChain(
            joints=tuple(names[j] for j in arm),
            fingers=tuple(names[j] for j in hand),
            eef_body=_name(model, mujoco.mjtObj.mjOBJ_BODY, eef),
            eef_by_name=eef_by_name,
            grip_site=_grip_site(model, eef),
        )
    fingers |= set(named)  # fingers on no arm (a finger-named joint on the torso) are a hand's too
    told = {*base, *fingers, *parts["head"], *(j for side in sides.values() for j in side)}
    torso = [j for j in joints if j not in told]  # named torso, or on the midline between the arms
    right = arms["right"]
    return Tree(
        joints=tuple(names.values()),
        arm=right.joints,
        fingers=tuple(names[j] for j in joints if j in fingers),
        base=tuple(names[j] for j in base),
        torso=tuple(names[j] for j in torso),
        head=tuple(names[j] for j in parts["head"]),
        eef_body=right.eef_body,
        eef_by_name=right.eef_by_name,
        grip_site=right.grip_site,
        wheels=tuple(names[j] for j in wheels),
        arms=arms,
        arms_by_name=by_name,
    )
