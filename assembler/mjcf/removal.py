"""Remove joints together with everything that drives, couples or measures them.

robosuite's ``_remove_joint_actuation`` handles motors and position actuators only and leaves
velocity/general actuators, sensors of removed actuators and single-joint equalities dangling or
crashing. Here removal is closed over references: a removed joint takes with it every actuator
on it (any type), every fixed tendon through it and the actuators on that tendon, every joint
equality naming it, and every sensor of any removed joint, tendon or actuator.
"""

from __future__ import annotations

from collections.abc import Iterable

import mujoco

FREE = mujoco.mjtJoint.mjJNT_FREE
JOINT_TRANSMISSIONS = (mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtTrn.mjTRN_JOINTINPARENT)


def _tendon_joints(tendon: mujoco.MjsTendon) -> set[str]:
    names = set()
    for wrap in tendon.path:
        if wrap.type == mujoco.mjtWrap.mjWRAP_JOINT:
            names.add(wrap.target.name)
    return names


def remove_joints(spec: mujoco.MjSpec, names: Iterable[str]) -> None:
    """Delete the named joints and every element that references them (see the module docstring)."""
    joints = set(names)
    if not joints:
        return
    tendons = {t.name for t in spec.tendons if _tendon_joints(t) & joints}
    actuators = set()
    for actuator in list(spec.actuators):
        on_joint = actuator.trntype in JOINT_TRANSMISSIONS and actuator.target in joints
        on_tendon = actuator.trntype == mujoco.mjtTrn.mjTRN_TENDON and actuator.target in tendons
        if on_joint or on_tendon:
            actuators.add(actuator.name)
            spec.delete(actuator)
    for sensor in list(spec.sensors):
        measured = {
            mujoco.mjtObj.mjOBJ_JOINT: joints,
            mujoco.mjtObj.mjOBJ_TENDON: tendons,
            mujoco.mjtObj.mjOBJ_ACTUATOR: actuators,
        }.get(sensor.objtype, set())
        if sensor.objname in measured:
            spec.delete(sensor)
    for equality in list(spec.equalities):
        if (
            equality.type == mujoco.mjtEq.mjEQ_JOINT
            and {equality.name1, equality.name2} & joints
            or equality.type == mujoco.mjtEq.mjEQ_TENDON
            and {equality.name1, equality.name2} & tendons
        ):
            spec.delete(equality)
    for tendon in list(spec.tendons):
        if tendon.name in tendons:
            spec.delete(tendon)
    for joint in list(spec.joints):
        if joint.name in joints:
            spec.delete(joint)


def remove_free_joints(spec: mujoco.MjSpec) -> None:
    """Delete every free joint (a floating root becomes welded to its parent)."""
    for joint in list(spec.joints):
        if joint.type == FREE:
            spec.delete(joint)
