"""RA601: a home pose outside the joints' ranges.

MuJoCo accepts a keyframe anywhere; the joint limit then acts at once, with a jolt, and position
servos fight it. Usually an ``init_qpos`` value is in degrees, in the wrong order, or for another
MJCF revision.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.compiler.keyframe import HOME_KEY
from assembler.spec.fieldpath import FieldPath

LIMIT_TOLERANCE = 1e-6
"""Rounding slack (rad or m) when comparing a keyframe value with a range bound."""

RANGED = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
"""Joint types with a range (MuJoCo's enum as plain ints, which numpy values compare with)."""


def keyframe_outside_limits(target: LintTarget) -> Iterator[Finding]:
    """RA601 (error): the ``home`` keyframe puts a limited joint outside its range."""
    model = target.model
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    if key < 0:
        return
    for joint in range(model.njnt):
        if not model.jnt_limited[joint] or int(model.jnt_type[joint]) not in RANGED:
            continue
        value = float(model.key_qpos[key, model.jnt_qposadr[joint]])
        low, high = (float(v) for v in model.jnt_range[joint])
        if low - LIMIT_TOLERANCE <= value <= high + LIMIT_TOLERANCE:
            continue
        name, bounds = model.joint(joint).name, f"[{low:.6g}, {high:.6g}]"
        part = target.part_of(name)
        if part is not None and part.spec.init_qpos is not None and name in part.joints:
            index = part.joints.index(name)
            location = target.spec_location(part, FieldPath(("init_qpos", index)))
            source = f"init_qpos[{index}]"
        else:
            location = target.element_location(("joint",), name)
            source = "the joint's ref (qpos0)"
        yield Finding(
            code="RA601",
            severity="error",
            subject=name,
            why=f"the home keyframe sets {value:.6g} ({source}), outside the joint's range {bounds}",
            fix=f"bring {source} within {bounds} (radians for hinges), or fix the joint's range",
            location=location,
        )
