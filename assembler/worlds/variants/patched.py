"""Variant files without a compile each: the robot is compiled and emitted once per process, and each
variant's XML is that text with the values its patch changes put in.

A variant differs from the plan's robot (its ``--set`` overrides applied, nothing varied) in what
:func:`~assembler.build.patchable.model_patch` finds between the two: the resolved joint,
actuator, friction and home-pose tables. Those are attribute values of named elements in the
robot's emitted MJCF: a joint's ``damping``/``frictionloss``/``armature``/``stiffness``, an
actuator's ``gainprm``/``biasprm``/``gear``/``ctrlrange``/``forcerange``, a geom's ``friction``
and the ``home`` key's ``qpos`` and ``ctrl``. A damping ratio is written as MuJoCo's compiler
reads one (a positive ``biasprm[2]``), so MuJoCo resolves it at load exactly as in a full compile.
Everything else, ``bodies:`` scales included (mass, inertia and geometry live in several
elements' attributes), is built and compiled the full way (:func:`PatchedXml.xml` returns None).

Every written file is still a model MuJoCo accepts, without compiling it: the text is the robot's
XML, which MuJoCo compiled in this process, with values of the same elements and attributes that
a patch describes, each validated by the spec's schema first. What MuJoCo's compiler refuses in
those attributes (a limited actuator's control or force range that does not increase) the schema
refuses too, and it is stricter elsewhere (no negative or non-finite joint values, which MuJoCo
takes); so such a variant is reported with the schema's line and not written
(tests/worlds/test_variants.py shows each refusal against MuJoCo's own load of the edited text).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import mujoco
import numpy as np

from assembler.build.compile import compile_and_emit
from assembler.build.patch_inputs import Resolved, resolve_variant
from assembler.build.patchable import ModelPatch, NotPatchable, model_patch
from assembler.build.service import default_store, entry_key
from assembler.mjcf.keyframe import HOME_KEY, home_control
from assembler.models import RobotModel
from assembler.registry.instances import assemble
from assembler.spec.documents import Override
from assembler.worlds.variants.xml_text import NotInText, XmlText, numbers

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


TEXT_SECTIONS = frozenset({"joint_defaults", "joints", "actuators", "geoms", "init_qpos"})
"""Spec fields whose changes are written as edits of the text (when the patch has no structural change)."""

Edits = dict[tuple[str, str], dict[str, str]]


@dataclass
class PatchedXml:
    """The plan's robot, compiled and emitted once, and the variants written as edits of its text."""

    robot: RobotModel
    resolved: Resolved
    model: mujoco.MjModel
    """The robot's compiled model; rows a variant changes are put back after computing its home controls."""
    text: XmlText
    grippers: Mapping[str, str | None]
    base: str | None

    @classmethod
    def of(
        cls,
        robot: str,
        idn: int | str,
        base: str | None,
        grippers: Mapping[str, str | None],
        fixed: Sequence[Override],
        cache: bool,
        meshes: bool,
    ) -> PatchedXml:
        """The robot with the ``fixed`` overrides: its model and XML from the compiled-model cache
        when an entry holds both (``cache``), else compiled once (meshes from the mesh store unless
        ``meshes`` is False); nothing is stored."""
        made = assemble(robot, idn, base, grippers, list(fixed))
        key = entry_key(made.build_inputs(), cache)
        entry = default_store().entry(key) if key is not None else None
        if entry is not None and entry.xml:  # both are checked against their files as they load
            xml = made.get_xml(cache=True, store=False, meshes=meshes)
            model = made.get_model(cache=True, store=False)
        else:
            model, xml = compile_and_emit(made.mjspec, made.assembly_home(), made.describe(), meshes=meshes)
        return cls(made, Resolved.of(made), model, XmlText(xml), grippers, base)

    def xml(self, overrides: Sequence[Override]) -> str | None:
        """The variant with ``overrides`` (all of them, the fixed ones too) as MJCF text, or None when
        it must be compiled; raises :class:`~assembler.errors.SpecError` for a value its spec refuses."""
        variant = resolve_variant(self.robot, self.resolved, overrides, self.grippers, self.base)
        try:
            patch = model_patch(self.model, self.resolved, variant)
        except NotPatchable:
            return None
        if not set(patch.fields) <= WRITTEN:
            return None  # bodies: scales, written in several elements: compiled
        try:
            return self.text.edited(self._edits(patch))
        except NotInText:
            return None

    def _edits(self, patch: ModelPatch) -> Edits:
        model, edits = self.model, Edits()
        for name, row, value in patch.entries:
            if name in JOINT_ATTRIBUTES:
                joint = int(row if name == "jnt_stiffness" else model.dof_jntid[row])
                self._joint(edits, model.joint(joint).name, JOINT_ATTRIBUTES[name], float(np.ravel(value)[0]))
            elif name in ACTUATOR_ATTRIBUTES:
                values = np.array(value, dtype=float)
                if name == "actuator_biasprm" and row in patch.dampratio:
                    values[2] = patch.dampratio[row]  # as MuJoCo's compiler reads a dampratio
                trimmed = name in ("actuator_gainprm", "actuator_biasprm")
                text = numbers(values) if trimmed else " ".join(repr(float(v)) for v in values)
                element = self.text.find("general", model.actuator(row).name)
                edits.setdefault(element, {})[ACTUATOR_ATTRIBUTES[name]] = text
            elif name == "geom_friction":
                element = self.text.find("geom", model.geom(row).name)
                edits.setdefault(element, {})["friction"] = " ".join(repr(float(v)) for v in value)
        self._home(edits, patch)
        return edits

    def _joint(self, edits: Edits, joint: str, attribute: str, value: float) -> None:
        element = self.text.find("joint", joint)
        written = self.text.attribute("joint", joint, attribute)
        rest = written.split()[1:] if written is not None and attribute in ("damping", "stiffness") else []
        edits.setdefault(element, {})[attribute] = " ".join([repr(value), *rest])

    def _home(self, edits: Edits, patch: ModelPatch) -> None:
        """The home key's qpos and the controls that hold it, computed as the compile computes them
        (on the robot's model with this variant's rows in, then put back)."""
        holding = {"key_qpos", "actuator_gainprm", "actuator_biasprm", "actuator_ctrlrange"}
        if not holding & set(patch.fields) or not self.model.nkey:
            return
        model, home = self.model, self.model.key(HOME_KEY).id
        kept = [
            (name, row, getattr(model, name)[row].copy()) for name, row, _ in patch.entries if name in holding
        ]
        try:
            for name, row, value in patch.entries:
                if name in holding:
                    getattr(model, name)[row] = value
            qpos = model.key_qpos[home].copy()
            ctrl = home_control(model, qpos)
        finally:
            for name, row, value in reversed(kept):
                getattr(model, name)[row] = value
        element = self.text.find("key", HOME_KEY)
        edits.setdefault(element, {})["qpos"] = " ".join(repr(float(v)) for v in qpos)
        if model.nu:
            edits[element]["ctrl"] = " ".join(repr(float(v)) for v in ctrl)
