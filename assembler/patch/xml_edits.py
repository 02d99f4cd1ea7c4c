"""A patch written as edits of the robot's emitted MJCF: a variant's XML without building or emitting it.

A variant that a patch describes (:func:`~assembler.patch.patchable.model_patch`) differs from its
robot in attribute values of named elements of the robot's emitted MJCF: a joint's
``damping``/``frictionloss``/``armature``/``stiffness``, an actuator's ``gainprm``/``biasprm``/
``gear``/``ctrlrange``/``forcerange``, a geom's ``friction`` and the ``home`` key's ``qpos`` and
``ctrl``. A damping ratio is written as MuJoCo's compiler reads one (a positive ``biasprm[2]``), so
MuJoCo resolves it at load exactly as in a full compile. Everything else, ``bodies:`` scales
included (mass, inertia and geometry live in several elements' attributes), cannot be written so:
:func:`patched_text` returns None and the caller builds the variant the full way.

Used by ``assembler variants`` (one emission per process, each variant an edit of it) and by
``get_xml()``/``save()`` of a robot with overrides whose plain robot's XML is in the cache.
"""

from __future__ import annotations

import mujoco
import numpy as np

from assembler.compiler.keyframe import HOME_KEY, home_control
from assembler.mjcf.emit import NotInText, XmlText, numbers
from assembler.patch.derived import ModelPatch

JOINT_ATTRIBUTES = {
    "dof_damping": "damping",
    "dof_frictionloss": "frictionloss",
    "dof_armature": "armature",
    "jnt_stiffness": "stiffness",
}
"""Model field -> the joint attribute that sets it (a polynomial's first coefficient for damping
and stiffness: the others are kept as written)."""

ACTUATOR_ATTRIBUTES = {
    "actuator_gainprm": "gainprm",
    "actuator_biasprm": "biasprm",
    "actuator_gear": "gear",
    "actuator_ctrlrange": "ctrlrange",
    "actuator_forcerange": "forcerange",
}
WRITTEN = {*JOINT_ATTRIBUTES, *ACTUATOR_ATTRIBUTES, "geom_friction", "key_qpos"}
"""The model fields a patch may write for the variant to be written as edited text."""

HOLDING = {"key_qpos", "actuator_gainprm", "actuator_biasprm", "actuator_ctrlrange"}
"""Fields the home key's controls depend on (which actuators hold a position, and within what range)."""

Edits = dict[tuple[str, str], dict[str, str]]


def patched_text(model: mujoco.MjModel, text: XmlText, patch: ModelPatch) -> str | None:
    """The robot's emitted XML ``text`` (of the compiled ``model``, left as it is) with the values
    ``patch`` writes put in; None when the patch writes a field no attribute holds alone or an
    element it edits is not in the text exactly once."""
    if not set(patch.fields) <= WRITTEN:
        return None
    try:
        return text.edited(_edits(model, text, patch))
    except NotInText:
        return None


def _edits(model: mujoco.MjModel, text: XmlText, patch: ModelPatch) -> Edits:
    edits = Edits()
    for name, row, value in patch.entries:
        if name in JOINT_ATTRIBUTES:
            joint = int(row if name == "jnt_stiffness" else model.dof_jntid[row])
            _joint(text, edits, model.joint(joint).name, JOINT_ATTRIBUTES[name], float(np.ravel(value)[0]))
        elif name in ACTUATOR_ATTRIBUTES:
            values = np.array(value, dtype=float)
            if name == "actuator_biasprm" and row in patch.dampratio:
                values[2] = patch.dampratio[row]  # as MuJoCo's compiler reads a dampratio
            trimmed = name in ("actuator_gainprm", "actuator_biasprm")
            written = numbers(values) if trimmed else " ".join(repr(float(v)) for v in values)
            element = text.find("general", model.actuator(row).name)
            edits.setdefault(element, {})[ACTUATOR_ATTRIBUTES[name]] = written
        elif name == "geom_friction":
            element = text.find("geom", model.geom(row).name)
            edits.setdefault(element, {})["friction"] = " ".join(repr(float(v)) for v in value)
    _home(model, text, edits, patch)
    return edits


def _joint(text: XmlText, edits: Edits, joint: str, attribute: str, value: float) -> None:
    element = text.find("joint", joint)
    written = text.attribute("joint", joint, attribute)
    rest = written.split()[1:] if written is not None and attribute in ("damping", "stiffness") else []
    edits.setdefault(element, {})[attribute] = " ".join([repr(value), *rest])


def _home(model: mujoco.MjModel, text: XmlText, edits: Edits, patch: ModelPatch) -> None:
    """The home key's qpos and the controls that hold it, computed as the compile computes them
    (on the robot's model with this variant's rows in, then put back)."""
    if not HOLDING & set(patch.fields) or not model.nkey:
        return
    home = model.key(HOME_KEY).id
    kept = [
        (name, row, getattr(model, name)[row].copy()) for name, row, _ in patch.entries if name in HOLDING
    ]
    try:
        for name, row, value in patch.entries:
            if name in HOLDING:
                getattr(model, name)[row] = value
        qpos = model.key_qpos[home].copy()
        ctrl = home_control(model, qpos)
    finally:
        for name, row, value in reversed(kept):
            getattr(model, name)[row] = value
    element = text.find("key", HOME_KEY)
    edits.setdefault(element, {})["qpos"] = " ".join(repr(float(v)) for v in qpos)
    if model.nu:
        edits[element]["ctrl"] = " ".join(repr(float(v)) for v in ctrl)
