"""What a URDF says that MuJoCo's import may lose, written into the imported MjSpec.

- ``<mimic>``: a joint equality ``follower = multiplier * leader + offset`` (MuJoCo's own import
  drops mimic silently before 4.0 and adds it since; either way the spec ends with exactly one); a
  ``<mimic>`` MuJoCo ignores (of a fixed joint, of itself) is ignored and said in a note;
- ``<limit lower upper>``: the joint is limited explicitly, so no ``autolimits`` setting of the
  assembly it lands in can unlimit it; ``<limit effort>``: its actuator force range;
- geoms follow robosuite's convention: ``<visual>`` in group 1 without contacts, ``<collision>``
  in group 0; unnamed geoms are named ``<link>_visual`` / ``<link>_collision`` (``_1``, ``_2``, ...
  when a link has several) so that lint, important geoms and contact lists can name them;
- a link welded to the world (a fixed base link) does not collide with its moving children: MuJoCo
  skips parent-child contacts except with the world, so a kept fixed base link would otherwise
  touch its first link wherever their meshes meet at the joint (MuJoCo's own import, which fuses
  the base link into the world, has the same contacts);
- on request (a spec's ``balance_inertia``), a link inertia that violates A + B >= C is made
  isotropic at the mean of its moments, as MuJoCo's ``balanceinertia`` does, and named in a note.
"""

from __future__ import annotations

from collections import Counter
from collections.abc import Sequence

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.mjcf import COLLISION_GROUP, VISUAL_GROUP
from assembler.urdf.document import Mimic, UrdfDocument

MOVING = (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)

MUJOCO_IGNORES = "as MuJoCo's URDF import"
"""The words of every line saying that a value of the URDF is left out as MuJoCo's own import leaves it
out (``new --strict`` refuses such a file)."""


def _joint_equality(spec: mujoco.MjSpec, follower: str, leader: str) -> mujoco.MjsEquality | None:
    for equality in spec.equalities:
        if equality.type == mujoco.mjtEq.mjEQ_JOINT and (equality.name1, equality.name2) == (
            follower,
            leader,
        ):
            return equality
    return None


def add_mimics(spec: mujoco.MjSpec, mimics: Sequence[Mimic], shown: str) -> dict[Mimic, str]:
    """One joint equality per ``<mimic>``; returns a line for each ``<mimic>`` ignored, as MuJoCo's URDF
    import ignores it (no error): one of a joint of itself, or of a joint that cannot move (Talos'
    grippers mimic on fixed joints)."""
    ignored: dict[Mimic, str] = {}
    for mimic in mimics:
        if mimic.leader == mimic.follower:  # MuJoCo's import drops it without a word
            ignored[mimic] = (
                f"{shown}:{mimic.line}: <mimic> of joint '{mimic.follower}' is ignored, as MuJoCo's URDF "
                "import ignores it: the joint mimics itself"
            )
            continue
        joints = {name: spec.joint(name) for name in (mimic.follower, mimic.leader)}
        still = [name for name, joint in joints.items() if joint is None or joint.type not in MOVING]
        if still:
            ignored[mimic] = (
                f"{shown}:{mimic.line}: <mimic> of joint '{mimic.follower}' (following '{mimic.leader}') is "
                f"ignored, as MuJoCo's URDF import ignores it: '{still[0]}' is not a revolute, continuous or "
                "prismatic joint"
            )
            continue
        equality = _joint_equality(spec, mimic.follower, mimic.leader)
        if equality is None:
            equality = spec.add_equality()
            equality.type = mujoco.mjtEq.mjEQ_JOINT
            equality.objtype = mujoco.mjtObj.mjOBJ_JOINT
            equality.name1, equality.name2 = mimic.follower, mimic.leader
        data = list(equality.data)  # past the polynomial, MuJoCo's defaults (as an XML <joint> gets them)
        data[:5] = [mimic.offset, mimic.multiplier, 0.0, 0.0, 0.0]  # polycoef: q1 = c0 + c1 * q2 + ...
        equality.data = data
    return ignored


def set_limits(spec: mujoco.MjSpec, document: UrdfDocument) -> None:
    """Position limits and effort limits as explicit ranges, whatever the assembly's autolimits."""
    true, false = mujoco.mjtLimited.mjLIMITED_TRUE, mujoco.mjtLimited.mjLIMITED_FALSE
    for joint in spec.joints:
        if joint.type not in MOVING:
            continue
        joint.limited = true if document.limited.get(joint.name, False) else false
        effort = document.efforts.get(joint.name)
        if effort is not None:
            joint.actfrcrange = [-effort, effort]
            joint.actfrclimited = true
        else:
            joint.actfrclimited = false


def is_visual(geom: mujoco.MjsGeom) -> bool:
    """A geom MuJoCo made from a URDF ``<visual>`` (it takes part in no contact)."""
    return bool(geom.contype == 0 and geom.conaffinity == 0)


def robosuite_groups(spec: mujoco.MjSpec) -> None:
    """Visual geoms in group 1 without contacts, collision geoms in group 0, every geom named."""
    taken = {geom.name for geom in spec.geoms if geom.name}
    for body in spec.bodies[1:]:
        geoms = list(body.geoms)
        kinds = ["visual" if is_visual(geom) else "collision" for geom in geoms]
        totals = Counter(kinds)
        seen: Counter[str] = Counter()
        for geom, kind in zip(geoms, kinds, strict=True):
            geom.group = VISUAL_GROUP if kind == "visual" else COLLISION_GROUP
            if kind == "visual":
                geom.density = 0.0  # a visual geom adds no mass
            seen[kind] += 1
            if geom.name:
                continue
            name = f"{body.name}_{kind}" + (f"_{seen[kind]}" if totals[kind] > 1 else "")
            while name in taken:
                name += "_"
            geom.name = name
            taken.add(name)


def _moments(body: mujoco.MjsBody) -> tuple[NDArray[np.float64], bool]:
    """The body's principal moments of inertia, and whether it gives a full inertia matrix."""
    full = np.array(body.fullinertia, dtype=float)
    if np.isnan(full[0]):
        return np.array(body.inertia, dtype=float), False
    xx, yy, zz, xy, xz, yz = full
    matrix = np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]])
    return np.linalg.eigvalsh(matrix), True


def unbalanced_inertias(spec: mujoco.MjSpec) -> list[str]:
    """The bodies whose given inertia violates A + B >= C (MuJoCo refuses them without balanceinertia)."""
    return [body.name for body in spec.bodies[1:] if _unbalanced(body)]


def _unbalanced(body: mujoco.MjsBody) -> bool:
    if body.mass <= 0:
        return False
    low, middle, high = np.sort(_moments(body)[0])
    return bool(low + middle < high)


def _numbers(values: NDArray[np.float64]) -> str:
    return ", ".join(f"{v:.6g}" for v in values)


def balance_inertias(spec: mujoco.MjSpec) -> list[str]:
    """Make every inertia that violates A + B >= C isotropic at its mean moment; one line per body
    changed, naming it with its inertia before and after (a full inertia's products are dropped, and
    one whose matrix is not positive definite, which MuJoCo refuses even with balanceinertia, is said so)."""
    changed = []
    for body in spec.bodies[1:]:
        if not _unbalanced(body):
            continue
        moments, full = _moments(body)
        mean = float(np.mean(moments))
        if full:
            before = f"full inertia ({_numbers(np.array(body.fullinertia, dtype=float))})"
            body.fullinertia = [mean, mean, mean, 0.0, 0.0, 0.0]
        else:
            before = f"diagonal inertia ({_numbers(np.array(body.inertia, dtype=float))})"
            body.inertia = [mean, mean, mean]
        why = "violates A + B >= C"
        if np.min(moments) <= 0:
            why = (
                f"has principal moments ({_numbers(np.sort(moments))}) that are not all positive, which "
                "MuJoCo refuses even with balanceinertia"
            )
        changed.append(
            f"link '{body.name}': {before} {why}: made diagonal ({_numbers(np.array([mean] * 3))}), "
            "isotropic at the mean of its principal moments"
        )
    return changed


def _welded_to_world(body: mujoco.MjsBody) -> bool:
    while body.name != "world":
        if len(body.joints):
            return False
        body = body.parent
    return True


def exclude_welded_parents(spec: mujoco.MjSpec) -> list[tuple[str, str]]:
    """Exclude contacts between the bodies welded to the world and the moving bodies attached to
    them (MuJoCo's filterparent, which treats a body and everything welded to it as one, skips the
    world); returns the pairs."""
    static = [body for body in spec.bodies[1:] if _welded_to_world(body)]
    pairs = []
    for body in spec.bodies[1:]:
        if len(body.joints) and body.parent.name != "world" and _welded_to_world(body.parent):
            for other in static:
                exclude = spec.add_exclude()
                exclude.bodyname1, exclude.bodyname2 = other.name, body.name
                pairs.append((other.name, body.name))
    return pairs
