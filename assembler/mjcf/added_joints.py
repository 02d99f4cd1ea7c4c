"""Add a spec's declared joints (and their velocity actuators) to a part's MjSpec, or a free joint."""

from __future__ import annotations

from collections.abc import Sequence

import mujoco

from assembler.errors import MjcfError, summarize_names
from assembler.spec.schema.added_joints import AddedJoint, VelocityActuator

_TYPES = {"slide": mujoco.mjtJoint.mjJNT_SLIDE, "hinge": mujoco.mjtJoint.mjJNT_HINGE}


def add_joints(spec: mujoco.MjSpec, joints: Sequence[AddedJoint]) -> None:
    """Add each joint to its body (default: the root body), then its actuator, in the given order."""
    for added in joints:
        body = spec.worldbody.first_body() if added.body is None else spec.body(added.body)
        if body is None:
            names = [b.name for b in spec.bodies if b.name and b.name != "world"]
            raise MjcfError(
                f"added joint '{added.name}': no body '{added.body}'. Bodies: {summarize_names(names)}"
            )
        joint = body.add_joint(
            name=added.name, type=_TYPES[added.type], axis=list(added.axis), pos=list(added.pos)
        )
        joint.armature = added.armature
        joint.frictionloss = added.frictionloss
        joint.damping = [added.damping] + [0.0] * (len(joint.damping) - 1)
        joint.limited = mujoco.mjtLimited.mjLIMITED_TRUE if added.range else mujoco.mjtLimited.mjLIMITED_FALSE
        if added.range:
            joint.range = list(added.range)
        if added.actuator is not None:
            _add_velocity_actuator(spec, added.name, added.actuator)


def add_free_joint(spec: mujoco.MjSpec) -> None:
    """Give the root body a free joint (it floats); it must have no joint yet."""
    root = spec.worldbody.first_body()
    if len(root.joints):
        names = ", ".join(joint.name or "(unnamed)" for joint in root.joints)
        raise MjcfError(
            f"the root body '{root.name}' already has joints ({names}); a free joint must be its only "
            "joint (a file with a free joint floats already: leave add_free_joint out)"
        )
    root.add_freejoint()


def _add_velocity_actuator(spec: mujoco.MjSpec, joint: str, declared: VelocityActuator) -> None:
    actuator = spec.add_actuator(name=declared.name, target=joint, trntype=mujoco.mjtTrn.mjTRN_JOINT)
    actuator.set_to_velocity(kv=declared.kv)
    actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
    actuator.ctrlrange = list(declared.ctrlrange)
    if declared.forcerange is not None:
        actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_TRUE
        actuator.forcerange = list(declared.forcerange)
