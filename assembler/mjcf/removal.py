"""Remove joints (or bodies) together with everything that drives, couples or measures them.

robosuite's ``_remove_joint_actuation`` handles motors and position actuators only and leaves
velocity/general actuators, sensors of removed actuators and single-joint equalities dangling or
crashing. Here removal is closed over references: a removed joint takes with it every actuator
on it (any type), every fixed tendon through it and the actuators on that tendon, every joint
equality naming it, and every sensor of any removed joint, tendon or actuator.
"""

from __future__ import annotations

from collections.abc import Iterable

import mujoco

from assembler.mjcf.versions import mujoco_at_least

FREE = mujoco.mjtJoint.mjJNT_FREE
JOINT_TRANSMISSIONS = (mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtTrn.mjTRN_JOINTINPARENT)


def _tendon_joints(spec: mujoco.MjSpec) -> dict[str, set[str]]:
    """Each tendon's joints by name (only fixed tendons have any)."""
    if not spec.tendons:
        return {}
    if not mujoco_at_least(3, 11):
        # Before MuJoCo 3.11 the wraps of a copied spec (every part's spec is a copy of the file's)
        # have no target: reading wrap.target crashes the interpreter. The compiled model has them.
        model = spec.compile()
        return {
            model.tendon(t).name: {
                model.joint(model.wrap_objid[w]).name
                for w in range(model.tendon_adr[t], model.tendon_adr[t] + model.tendon_num[t])
                if model.wrap_type[w] == mujoco.mjtWrap.mjWRAP_JOINT
            }
            for t in range(model.ntendon)
        }
    return {
        tendon.name: {w.target.name for w in tendon.path if w.type == mujoco.mjtWrap.mjWRAP_JOINT}
        for tendon in spec.tendons
    }


def remove_joints(spec: mujoco.MjSpec, names: Iterable[str]) -> None:
    """Delete the named joints and every element that references them (see the module docstring)."""
    joints = set(names)
    if not joints:
        return
    tendons = {name for name, through in _tendon_joints(spec).items() if through & joints}
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


def _subtree(body: mujoco.MjsBody) -> list[mujoco.MjsBody]:
    bodies = [body]
    for child in body.bodies:
        bodies += _subtree(child)
    return bodies


def remove_bodies(spec: mujoco.MjSpec, names: Iterable[str]) -> None:
    """Delete the named bodies with everything below them and everything that references what goes:
    the joints' actuators, tendons, equalities and sensors (:func:`remove_joints`), sensors of their
    sites, bodies and geoms, welds and connects to them, and contact exclusions naming them."""
    bodies = [b for name in names if (top := spec.body(name)) is not None for b in _subtree(top)]
    if not bodies:
        return
    remove_joints(spec, [j.name for body in bodies for j in body.joints if j.type != FREE])
    body_names = {body.name for body in bodies}
    element_names = body_names | {e.name for body in bodies for e in [*body.sites, *body.geoms] if e.name}
    for sensor in list(spec.sensors):
        if sensor.objname in element_names or sensor.refname in element_names:
            spec.delete(sensor)
    for equality in list(spec.equalities):
        if equality.type != mujoco.mjtEq.mjEQ_JOINT and {equality.name1, equality.name2} & element_names:
            spec.delete(equality)
    for exclude in list(spec.excludes):
        if {exclude.bodyname1, exclude.bodyname2} & body_names:
            spec.delete(exclude)
    for name in names:
        top = spec.body(name)
        if top is not None:
            spec.delete(top)


def remove_free_joints(spec: mujoco.MjSpec) -> None:
    """Delete every free joint (a floating root becomes welded to its parent)."""
    for joint in list(spec.joints):
        if joint.type == FREE:
            spec.delete(joint)
