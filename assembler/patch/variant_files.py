"""Variant files without a compile each: the robot is compiled and emitted once per process, and each
variant's XML is that text with the values its patch changes put in.

A variant differs from the plan's robot (its ``--set`` overrides applied, nothing varied) in what
:func:`~assembler.patch.patchable.model_patch` finds between the two: the resolved joint,
actuator, friction and home-pose tables. :mod:`assembler.patch.xml_edits` writes those as edits
of the robot's emitted XML; anything it cannot write (``bodies:`` scales) is built and compiled the
full way (:func:`PatchedXml.xml` returns None).

Every written file is still a model MuJoCo accepts, without compiling it: the text is the robot's
XML, which MuJoCo compiled in this process, with values of the same elements and attributes that
a patch describes, each validated by the spec's schema first. What MuJoCo's compiler refuses in
those attributes (a limited actuator's control or force range that does not increase) the schema
refuses too, and it is stricter elsewhere (no negative or non-finite joint values, which MuJoCo
takes); so such a variant is reported with the schema's line and not written
(tests/worlds/test_variants.py shows each refusal against MuJoCo's own load of the edited text).
"""

from __future__ import annotations

import copy
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from assembler.compiler.compile import compile_and_emit
from assembler.compiler.service import default_store, entry_key
from assembler.mjcf.emit import XmlText
from assembler.models import RobotModel
from assembler.patch.derived import ModelPatch, apply_patch
from assembler.patch.patchable import NotPatchable, model_patch
from assembler.patch.resolved import Resolved, resolve_variant
from assembler.patch.xml_edits import patched_text
from assembler.registry.instances import assemble
from assembler.spec.documents import Override

TEXT_SECTIONS = frozenset({"joint_defaults", "joints", "actuators", "geoms", "init_qpos"})
"""Spec fields whose changes are written as edits of the text (when the patch has no structural change)."""


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

    def _patch(self, overrides: Sequence[Override]) -> ModelPatch | None:
        """What makes the variant with ``overrides`` of the robot's model, or None when it must be
        compiled; raises :class:`~assembler.errors.SpecError` for a value its spec refuses."""
        variant = resolve_variant(self.robot, self.resolved, overrides, self.grippers, self.base)
        try:
            return model_patch(self.model, self.resolved, variant)
        except NotPatchable:
            return None

    def xml(self, overrides: Sequence[Override]) -> str | None:
        """The variant with ``overrides`` (all of them, the fixed ones too) as MJCF text, or None when
        it must be compiled; raises :class:`~assembler.errors.SpecError` for a value its spec refuses."""
        patch = self._patch(overrides)
        return None if patch is None else patched_text(self.model, self.text, patch)

    def surely_differ(self, first: Sequence[Override], second: Sequence[Override]) -> bool:
        """True when the variants with ``first`` and ``second`` are different models, told from their
        patches alone (no model made): one writes a value (beyond 1e-9) the other does not leave in
        the same place, and nothing MuJoCo derives after the patch overwrites it (a damping ratio's
        ``biasprm`` row is recomputed, so it never tells). False: the patches alone cannot tell."""
        mine_patch, their_patch = self._patch(first), self._patch(second)
        if mine_patch is None or their_patch is None:
            return False
        written = [_kept_values(mine_patch), _kept_values(their_patch)]
        for name, row in written[0].keys() | written[1].keys():
            plain = getattr(self.model, name)[row]
            mine, theirs = (values.get((name, row), plain) for values in written)
            if not np.allclose(mine, theirs, rtol=1e-9, atol=1e-12, equal_nan=True):
                return True
        return False

    def compiled(self, overrides: Sequence[Override]) -> mujoco.MjModel | None:
        """The model :meth:`xml`'s text of the same variant loads to (within 1e-10), patched in
        memory: no text is loaded, no mesh decoded. None when the variant must be compiled."""
        patch = self._patch(overrides)
        if patch is None:
            return None
        model = copy.copy(self.model)  # MuJoCo's mj_copyModel: arrays of its own
        apply_patch(model, patch)
        return model


def _kept_values(patch: ModelPatch) -> dict[tuple[str, int], Any]:
    """(field, row) -> what ``patch`` writes there and the patched model keeps."""
    return {
        (name, row): value
        for name, row, value in patch.entries
        if not (name == "actuator_biasprm" and row in patch.dampratio)
    }
