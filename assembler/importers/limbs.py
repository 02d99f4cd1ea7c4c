"""Legs and arms told apart by the kinematic tree's shape at the file's zero pose, for ``assembler new``.

A foot is a leaf body hanging well below the robot's root body, among its lowest bodies, at the end of
at least two moving joints: Solo12's ``FL_FOOT``, ANYmal's ``LF_FOOT``, the CMU humanoid's ``ltoes``.
A fixed-base arm has none (its root is its lowest body) and a wheel is one joint from its base. A
joint on the way to one foot is a leg joint; on the way to several (a waist above both legs) it moves
the torso. What moves and is no leg is an arm, and an arm's side is its name's (``left``, ``l_``...)
(or a mirror twin's: the CMU humanoid's ``lhumerusrx`` and ``rhumerusrx``) or, failing that, the side
of the root it lies on: the left foot's side (+y when the feet do not say, as robots face +x). A robot
without feet whose joints split so into two serial chains (Baxter, YuMi) has two arms
(:func:`two_arms`). Every answer is a guess that :mod:`assembler.importers.decisions` writes with its
reason.
"""

from __future__ import annotations

import re
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

FOOT_DROP = 0.25
"""A foot lies at least this fraction of the robot's height below its root body."""

FOOT_BAND = 0.15
"""... and within this fraction of the robot's height above its lowest body."""

LEFT_WORDS = re.compile(r"(^|[_/:.\-])(left|l)([_/:.\-]|$)|left", re.IGNORECASE)
RIGHT_WORDS = re.compile(r"(^|[_/:.\-])(right|r)([_/:.\-]|$)|right", re.IGNORECASE)
"""Side words in joint names (``arm_left_1_joint``, ``l_shoulder``)."""

MIDLINE = 0.04
"""A joint whose anchor lies within this fraction of the robot's height of the root's sagittal plane is
on the midline (a spine, a neck), on no side."""

MIN_ARM = 3
"""The fewest joints on the midline taken for one arm when no joint lies off it."""

MOVING = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE), int(mujoco.mjtJoint.mjJNT_BALL))


@dataclass(frozen=True)
class Limbs:
    """A legged robot's feet and joints, by MJCF name (joints in MuJoCo's order)."""

    feet: tuple[str, ...]
    legs: tuple[str, ...]
    """Joints on the way to exactly one foot."""
    waist: tuple[str, ...]
    """Joints on the way to several feet (they move the torso)."""
    arms: dict[str, tuple[str, ...]]
    """``right`` / ``left`` -> the joints of the arm on that side (none for a robot without arms)."""
    hands: dict[str, str]
    """``right`` / ``left`` -> the body at the end of that arm (where its branches, fingers, meet)."""
    sides_by_name: bool
    """True when the arms' sides come from their names, False from where they lie."""


def _path(model: mujoco.MjModel, body: int, root: int) -> list[int]:
    """The bodies from ``body`` up to (not including) ``root``, deepest first."""
    chain = []
    while body > 0 and body != root:
        chain.append(body)
        body = int(model.body_parentid[body])
    return chain


def _moving(model: mujoco.MjModel, bodies: list[int]) -> list[int]:
    return [
        j
        for j in range(model.njnt)
        if int(model.jnt_bodyid[j]) in bodies and int(model.jnt_type[j]) in MOVING
    ]


def _side(name: str, names: set[str]) -> str | None:
    """``left`` / ``right`` by the name's side word, or by a twin named with the other side's first
    letter (``lfemurrz`` beside ``rfemurrz``); None when the name does not say."""
    left, right = bool(LEFT_WORDS.search(name)), bool(RIGHT_WORDS.search(name))
    if left != right:
        return "left" if left else "right"
    twins = {"l": "r", "r": "l"}
    first = name[:1].lower()
    if first in twins and len(name) > 1 and twins[first] + name[1:] in names:
        return "left" if first == "l" else "right"
    return None


def _lateral(model: mujoco.MjModel, data: mujoco.MjData, feet: list[int]) -> NDArray[np.float64]:
    """The world's horizontal direction to the robot's left: from its right foot to its left one when
    the feet's names say which is which, else +y."""
    names = {_name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in feet}
    sided = {_side(_name(model, mujoco.mjtObj.mjOBJ_BODY, b), names): b for b in feet}
    if "left" in sided and "right" in sided:
        direction = data.xpos[sided["left"]] - data.xpos[sided["right"]]
        direction[2] = 0.0
        norm = float(np.linalg.norm(direction))
        if norm > 0:
            return np.asarray(direction / norm)
    return np.array([0.0, 1.0, 0.0])


def _name(model: mujoco.MjModel, kind: mujoco.mjtObj, index: int) -> str:
    return mujoco.mj_id2name(model, kind, index) or ""


def _end(model: mujoco.MjModel, leaves: list[int]) -> int:
    """The deepest body every leaf hangs from (a hand where its fingers branch off)."""
    shared = set(_path(model, leaves[0], 0))
    for leaf in leaves[1:]:
        shared &= set(_path(model, leaf, 0))
    return max(shared, key=lambda b: len(_path(model, b, 0))) if shared else leaves[0]


def _posed(model: mujoco.MjModel, root: int) -> tuple[mujoco.MjData, list[int], set[int], float]:
    """The file's zero pose, the bodies under ``root`` (with it), the bodies among them with children,
    and the robot's height (0 for a flat robot)."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    bodies = [b for b in range(1, model.nbody) if root in (b, *_path(model, b, 0))]
    parents = {int(model.body_parentid[b]) for b in bodies}
    heights = data.xpos[bodies, 2]
    return data, bodies, parents, float(heights.max() - heights.min())


def read_limbs(model: mujoco.MjModel, root: int, skip: set[int]) -> Limbs | None:
    """The legs, feet and arms of the robot under body ``root``, or None when it has fewer than two feet
    (an arm, a hand, a wheeled base). ``skip``: joints already told (fingers, head, mobile base)."""
    data, bodies, parents, span = _posed(model, root)
    if span <= 0:
        return None
    heights = data.xpos[bodies, 2]
    top, low = float(data.xpos[root, 2]), float(heights.min())
    feet = [
        b
        for b in bodies
        if b not in parents
        and data.xpos[b, 2] <= top - FOOT_DROP * span
        and data.xpos[b, 2] <= low + FOOT_BAND * span
        and len(_moving(model, _path(model, b, root))) >= 2
    ]
    if len(feet) < 2:
        return None
    on_paths: dict[int, int] = {}
    for foot in feet:
        for joint in _moving(model, _path(model, foot, root)):
            on_paths[joint] = on_paths.get(joint, 0) + 1
    legs = sorted(j for j, count in on_paths.items() if count == 1 and j not in skip)
    waist = sorted(j for j, count in on_paths.items() if count > 1 and j not in skip)
    rest = [j for j in _moving(model, bodies) if j not in on_paths and j not in skip]
    left = _lateral(model, data, feet)
    arms, hands, by_name = _arms(model, data, root, bodies, parents, rest, span * left)
    joint = mujoco.mjtObj.mjOBJ_JOINT
    return Limbs(
        feet=tuple(_name(model, mujoco.mjtObj.mjOBJ_BODY, b) for b in feet),
        legs=tuple(_name(model, joint, j) for j in legs),
        waist=tuple(_name(model, joint, j) for j in waist),
        arms={side: tuple(_name(model, joint, j) for j in found) for side, found in arms.items()},
        hands={side: _name(model, mujoco.mjtObj.mjOBJ_BODY, b) for side, b in hands.items()},
        sides_by_name=by_name,
    )


def _arms(
    model: mujoco.MjModel,
    data: mujoco.MjData,
    root: int,
    bodies: list[int],
    parents: set[int],
    rest: list[int],
    left: NDArray[np.float64],
) -> tuple[dict[str, list[int]], dict[str, int], bool]:
    """The moving joints that are no leg, split into a right and a left arm: each joint's side is its
    name's, else the side of the root its anchor lies on, off the midline; joints on the midline (a
    spine, a waist) belong to no arm, unless no joint is off it (one arm on a quadruped's back)."""
    every = {_name(model, mujoco.mjtObj.mjOBJ_JOINT, j) for j in range(model.njnt)}
    named = {j: _side(_name(model, mujoco.mjtObj.mjOBJ_JOINT, j), every) for j in rest}
    span = float(np.linalg.norm(left))
    by_name = bool(rest) and all(side is not None for side in named.values())
    sides: dict[str, list[int]] = {}
    for joint in rest:
        lateral = float((data.xanchor[joint] - data.xpos[root]) @ left) / span
        side = named[joint]
        if side is None and abs(lateral) > MIDLINE * span:
            side = "left" if lateral > 0 else "right"
        if side is not None:
            sides.setdefault(side, []).append(joint)
    if not sides and len(rest) >= MIN_ARM:  # one arm on the midline (a quadruped carrying an arm)
        sides = {"right": list(rest)}
    hands = {}
    for side, joints in sides.items():
        last = max((int(model.jnt_bodyid[j]) for j in joints), key=lambda b: len(_path(model, b, 0)))
        below = [b for b in bodies if b not in parents and last in (b, *_path(model, b, 0))]
        hands[side] = _end(model, below) if below else last
    return sides, hands, by_name


def serial_chain(model: mujoco.MjModel, joints: list[int]) -> list[int]:
    """Those of ``joints`` on the way from the world to the deepest of them: an arm's serial chain."""
    deepest = max((int(model.jnt_bodyid[j]) for j in joints), key=lambda b: len(_path(model, b, 0)))
    on_way = set(_path(model, deepest, 0))
    return [j for j in joints if int(model.jnt_bodyid[j]) in on_way]


def two_arms(model: mujoco.MjModel, root: int, skip: set[int]) -> tuple[dict[str, list[int]], bool] | None:
    """A robot without feet whose moving joints under ``root`` (but ``skip``: base, head, torso,
    fingers) split into a right and a left arm, told as :func:`_arms` tells a humanoid's (robots face
    +x, so +y is their left): each side's joints and whether their names told the sides. None unless
    each side has at least :data:`MIN_ARM` joints on a serial chain and neither chain runs through the
    other (one arm whose joints lie on both sides of its root, a UR5's, is no pair)."""
    data, bodies, parents, _ = _posed(model, root)
    rest = [j for j in _moving(model, bodies) if j not in skip]
    size = float(np.ptp(data.xpos[bodies], axis=0).max())  # an arm's height may be 0 (arms level)
    if size <= 0 or not rest:
        return None
    sides, _, by_name = _arms(model, data, root, bodies, parents, rest, np.array([0.0, size, 0.0]))
    if set(sides) != {"right", "left"}:
        return None
    chains = {side: serial_chain(model, joints) for side, joints in sides.items()}
    if any(len(chain) < MIN_ARM for chain in chains.values()):
        return None
    for side, other in (("right", "left"), ("left", "right")):  # a chain's last joint is its deepest
        deepest = set(_path(model, int(model.jnt_bodyid[chains[other][-1]]), 0))
        if any(int(model.jnt_bodyid[j]) in deepest for j in chains[side]):
            return None
    return sides, by_name
