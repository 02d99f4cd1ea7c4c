"""Reading and writing one scalar joint parameter on an MjSpec joint, whatever MuJoCo's version.

Since MuJoCo 3.7 ``damping`` and ``stiffness`` are polynomial coefficient arrays (element 0 is the
value MJCF's attribute sets); ``armature`` and ``frictionloss`` stay scalars.
"""

from __future__ import annotations

from collections.abc import Iterable

import mujoco
import numpy as np

FREE = mujoco.mjtJoint.mjJNT_FREE


def joint_attribute(joint: mujoco.MjsJoint, attribute: str) -> float:
    """A joint's scalar value of ``attribute`` (damping/stiffness: the linear coefficient)."""
    value = getattr(joint, attribute)
    return float(value[0]) if hasattr(value, "__len__") else float(value)


def set_joint_attribute_value(joint: mujoco.MjsJoint, attribute: str, value: float) -> None:
    """Set a scalar joint attribute on ``joint``."""
    current = getattr(joint, attribute)
    if hasattr(current, "__len__"):
        coefficients = np.array(current, dtype=float)
        coefficients[0] = value
        setattr(joint, attribute, coefficients)
    else:
        setattr(joint, attribute, value)


def free_joints(joints: Iterable[mujoco.MjsJoint]) -> int:
    """How many of ``joints`` are free joints."""
    return sum(joint.type == FREE for joint in joints)


def named_joints(mjspec: mujoco.MjSpec) -> list[str]:
    """Names of the spec's joints in MuJoCo's order, free joints excluded."""
    return [joint.name for joint in mjspec.joints if joint.type != FREE]
