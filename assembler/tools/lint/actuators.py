"""RA301-RA302: position servos that can command what the joint cannot do.

A position actuator whose ctrlrange reaches past its joint's range pushes the joint into its limit
(and a policy's action space includes unreachable targets); one on a joint without limits lets a
target wind the joint through itself. MuJoCo accepts both silently.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco
import numpy as np

from assembler.checks.finding import Finding
from assembler.checks.target import ACTUATOR_TAGS, LintTarget

RANGE_TOLERANCE = 1e-6
"""Rounding slack (rad or m) when comparing ranges."""

RANGED = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))
"""Joint types with a range (MuJoCo's enum as plain ints, which numpy values compare with)."""


def is_position_servo(model: mujoco.MjModel, actuator: int) -> bool:
    """True for an actuator on a joint whose force is kp * (ctrl - gear * q): ctrl is a position target."""
    kp = float(model.actuator_gainprm[actuator, 0])
    return bool(
        model.actuator_trntype[actuator] == mujoco.mjtTrn.mjTRN_JOINT
        and kp > 0
        and np.isclose(model.actuator_biasprm[actuator, 1], -kp)
    )


def _servos(target: LintTarget) -> Iterator[tuple[int, int, str, str]]:
    """(actuator, joint, actuator name, joint name) of every position servo on a hinge or slide joint."""
    model = target.model
    for actuator in range(model.nu):
        joint = int(model.actuator_trnid[actuator, 0])
        if is_position_servo(model, actuator) and int(model.jnt_type[joint]) in RANGED:
            name = target.element_name(mujoco.mjtObj.mjOBJ_ACTUATOR, actuator)
            yield actuator, joint, name, model.joint(joint).name


def ctrlrange_beyond_joint_range(target: LintTarget) -> Iterator[Finding]:
    """RA301 (warning): a position servo's targets reach outside its (limited) joint's range."""
    model = target.model
    for actuator, joint, name, joint_name in _servos(target):
        if not model.jnt_limited[joint]:
            continue
        low, high = (float(v) for v in model.jnt_range[joint])
        location = target.element_location(ACTUATOR_TAGS, name)
        if not model.actuator_ctrllimited[actuator]:
            yield Finding(
                code="RA301",
                severity="warning",
                subject=name,
                why=(
                    f"position servo without ctrlrange on joint {joint_name} "
                    f"(range [{low:.6g}, {high:.6g}]): any target is accepted"
                ),
                fix=f'set ctrlrange="{low:.6g} {high:.6g}" on the actuator',
                location=location,
            )
            continue
        gear = float(model.actuator_gear[actuator, 0]) or 1.0
        targets = sorted(float(c) / gear for c in model.actuator_ctrlrange[actuator])
        if targets[0] >= low - RANGE_TOLERANCE and targets[1] <= high + RANGE_TOLERANCE:
            continue
        excess = max(low - targets[0], targets[1] - high)
        shown, joint_range = _distinct(targets, [low, high])
        shown += f" (ctrlrange / gear {gear:g})" if gear != 1.0 else ""
        yield Finding(
            code="RA301",
            severity="warning",
            subject=name,
            why=(
                f"ctrlrange targets {shown} reach {excess:.2g} outside joint {joint_name}'s range "
                f"{joint_range}: the servo can push the joint into its limit"
            ),
            fix="narrow the actuator's ctrlrange to the joint's range (or fix the joint's range)",
            location=location,
        )


def _distinct(first: list[float], second: list[float]) -> tuple[str, str]:
    """Both ranges as text with the fewest digits (6 at least) that show they differ: a vendor's
    rounding can put a bound a few microradians out, which 6 digits would print as equal."""
    for digits in range(6, 18):
        texts = [f"[{a:.{digits}g}, {b:.{digits}g}]" for a, b in (first, second)]
        if texts[0] != texts[1]:
            break
    return texts[0], texts[1]


def unlimited_driven_joints(target: LintTarget) -> Iterator[Finding]:
    """RA302 (warning): a position servo drives a hinge or slide joint that has no range."""
    model = target.model
    for _, joint, name, joint_name in _servos(target):
        if model.jnt_limited[joint]:
            continue
        yield Finding(
            code="RA302",
            severity="warning",
            subject=joint_name,
            why=f"driven by position servo {name} but has no range: a target out of reach winds it on",
            fix='give the joint its mechanical range (range="low high"; with autolimits or limited="true")',
            location=target.element_location(("joint",), joint_name),
        )
