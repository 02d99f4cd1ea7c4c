"""Joints of a part's MjSpec: one parameter read and written whatever MuJoCo's version, which
attributes the file itself sets, the joints a spec adds, and joints (or bodies) removed together
with everything that drives, couples or measures them.

Reading and writing one scalar joint parameter on an MjSpec joint, whatever MuJoCo's version.

Since MuJoCo 3.7 ``damping`` and ``stiffness`` are polynomial coefficient arrays (element 0 is the
value MJCF's attribute sets); ``armature`` and ``frictionloss`` stay scalars.

Which joint attributes an MJCF file sets, by MuJoCo's own default resolution.

robosuite's rule "apply the default only where the model does not set it" needs to know whether
a joint's damping (say) comes from the file or from MuJoCo's built-in default. MjSpec reports
resolved values only, so we ask MuJoCo itself: parse the file a second time with an impossible
sentinel value in the main default class. A joint that still shows the sentinel inherits from
nothing the author wrote; any other value was set by the author, literally, through its class,
a nested class or an ancestor's ``childclass`` - exactly as MuJoCo will compile it.

Add a spec's declared joints (and their velocity actuators) to a part's MjSpec, or a free joint.

Remove joints (or bodies) together with everything that drives, couples or measures them.
robosuite's ``_remove_joint_actuation`` handles motors and position actuators only and leaves
velocity/general actuators, sensors of removed actuators and single-joint equalities dangling or
crashing. Here removal is closed over references: a removed joint takes with it every actuator
on it (any type), every fixed tendon through it and the actuators on that tendon, every joint
equality naming it, and every sensor of any removed joint, tendon or actuator.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterable, Mapping, Sequence

import mujoco
import numpy as np

from assembler.errors import MjcfError, summarize_names
from assembler.mjcf import installed_mujoco
from assembler.mjcf.installed_mujoco import mujoco_at_least
from assembler.spec.schema.added_joints import AddedJoint, VelocityActuator

FREE = mujoco.mjtJoint.mjJNT_FREE
JOINT_TRANSMISSIONS = (mujoco.mjtTrn.mjTRN_JOINT, mujoco.mjtTrn.mjTRN_JOINTINPARENT)


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


SENTINEL = -7.251e33
"""A value no author writes; it marks attributes the file leaves to MuJoCo's built-in default."""

SENSED_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")


def _main_joint_default(root: ET.Element) -> ET.Element:
    default = root.find("default")
    if default is None:
        default = ET.SubElement(root, "default")
    joint = default.find("joint")
    if joint is None:
        joint = ET.SubElement(default, "joint")
    return joint


Authored = dict[str, tuple[str, str]]
"""Attribute -> (how, class name): how is ``literal`` (on the joint element), ``main default``
(the file's class-less ``<default>``) or ``class`` (a default class, nested class or ``childclass``)."""


def authored_attributes(
    root: ET.Element, mjspec: mujoco.MjSpec, included: Mapping[str, bytes] | None = None
) -> list[Authored]:
    """For each joint of ``mjspec`` (in MjSpec order), the attributes the file sets and how.

    ``root`` is the file's parsed XML; it is not modified. ``included`` maps each ``<include file>``
    value to that file's bytes: the probe is parsed from memory, where MuJoCo cannot open files.
    """
    probe_root = ET.fromstring(ET.tostring(root))
    main_joint = _main_joint_default(probe_root)
    in_main = {a for a in SENSED_ATTRIBUTES if main_joint.get(a) is not None}
    for attribute in SENSED_ATTRIBUTES:
        if attribute not in in_main:
            main_joint.set(attribute, repr(SENTINEL))
    probe_xml = ET.tostring(probe_root, encoding="unicode")
    with installed_mujoco.collected():  # the file's own parse has shown them
        probe = mujoco.MjSpec.from_string(probe_xml, include=dict(included or {}))

    literal = {
        element.get("name"): element.attrib
        for element in root.iter("joint")
        if element.get("name") and element.get("joint") is None and element.get("joint1") is None
    }
    result: list[Authored] = []
    for joint, probed in zip(mjspec.joints, probe.joints, strict=True):
        own = literal.get(joint.name, {})
        sets: Authored = {}
        for attribute in SENSED_ATTRIBUTES:
            if attribute in own:
                sets[attribute] = ("literal", "")
            elif attribute in in_main:
                sets[attribute] = ("main default", "")
            elif joint_attribute(probed, attribute) != SENTINEL:
                sets[attribute] = ("class", joint.classname.name)
        result.append(sets)
    return result


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
    """Delete the named joints and every element that references them (see the module docstring's
    last paragraph)."""
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
