"""Each world's values of the fields a variant plan varies, from one compiled model patched in turn.

Every variant of the plan is resolved against the robot (a spec validation, no MJCF preparation),
turned into a patch (:mod:`assembler.patch.patchable`), written into one scratch model, its derived
constants recomputed with ``mj_setConst``, and the varied fields read back; then the scratch model
is restored. Nothing is compiled but the robot itself, and no model is copied per world.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import AssemblerError
from assembler.models import RobotModel
from assembler.patch.derived import apply_patch, dampratio_rule
from assembler.patch.patchable import ModelPatch, NotPatchable, model_patch
from assembler.patch.resolved import Resolved, resolve_variant
from assembler.spec.documents import Override

SET_CONST_OUTPUTS: tuple[str, ...] = (
    "body_subtreemass",
    "body_invweight0",
    "dof_invweight0",
    "actuator_acc0",
    "cam_pos0",
    "cam_poscom0",
    "cam_mat0",
    "light_pos0",
    "light_poscom0",
    "light_dir0",
    "tendon_length0",
    "tendon_invweight0",
    "geom_rbound",
    "geom_aabb",
)
"""Derived fields MuJoCo Warp's ``set_const`` writes: batched whenever anything varies, so that each
world keeps its own (an unbatched one would hold one world's values for all)."""

HOME_FIELDS: tuple[str, ...] = ("key_qpos", "key_ctrl")
"""The home keyframe's row: a world's initial state, not a model field of MuJoCo Warp."""


@dataclass
class WorldValues:
    """Per field, one row per world (``values[field][i]`` is world i's), and each world's home state."""

    values: dict[str, NDArray[np.float64]]
    qpos: NDArray[np.float64]
    ctrl: NDArray[np.float64]


def world_patches(
    robot: RobotModel, model: mujoco.MjModel, overrides: Sequence[Sequence[Override]], labels: Sequence[str]
) -> list[ModelPatch]:
    """Each world's patch of ``model`` (the compiled ``robot``); a world whose variant needs a compile
    is refused with its label (``world 3 (bodies[0].size_scale=1.2)``) and the field."""
    own = Resolved.of(robot)
    patches: list[ModelPatch] = []
    for items, label in zip(overrides, labels, strict=True):
        try:
            patches.append(model_patch(model, own, resolve_variant(robot, own, items)))
        except NotPatchable as error:
            raise NotPatchable(f"{label}: {error}") from None
    return patches


def world_values(model: mujoco.MjModel, patches: Sequence[ModelPatch], fields: Sequence[str]) -> WorldValues:
    """Apply each patch to ``model`` in turn (restored afterwards) and read ``fields`` and the home state."""
    written = sorted({name for patch in patches for name in patch.fields} | set(fields))
    saved = {name: getattr(model, name).copy() for name in written}
    stat = (model.stat.meaninertia, model.stat.meanmass)
    home = model.key("home").id if model.nkey else None
    values = {name: np.empty((len(patches), *getattr(model, name).shape)) for name in fields}
    qpos = np.empty((len(patches), model.nq))
    ctrl = np.empty((len(patches), model.nu))
    scratch = mujoco.MjData(model)
    rule = dampratio_rule(model, patches[0].dampratio) if patches else None  # once, off the compiled robot
    try:
        for world, patch in enumerate(patches):
            patch.dampratio_rule = rule
            apply_patch(model, patch, scratch)
            for name in fields:
                values[name][world] = getattr(model, name)
            qpos[world] = model.key_qpos[home] if home is not None else model.qpos0
            ctrl[world] = model.key_ctrl[home] if home is not None else 0.0
            for name, array in saved.items():
                getattr(model, name)[:] = array
    finally:
        for name, array in saved.items():
            getattr(model, name)[:] = array
        mujoco.mj_setConst(model, scratch)
        model.stat.meaninertia, model.stat.meanmass = stat
    return WorldValues(values, qpos, ctrl)


def refused_fields(
    patches: Sequence[ModelPatch], fields: set[str], batchable: set[str], labels: Sequence[str]
) -> None:
    """One line naming the first field a world varies that MuJoCo Warp has (``fields``) but cannot vary
    per world; fields it does not have (``bvh_aabb``, ``dof_M0``) do not reach it."""
    for patch, label in zip(patches, labels, strict=True):
        for name in patch.fields:
            if name in fields and name not in batchable and name not in HOME_FIELDS:
                raise AssemblerError(
                    f"{label}: varies {name}, which MuJoCo Warp cannot vary per world "
                    "(fields it can vary start with '*' in mujoco_warp's types.Model); "
                    "build such variants as separate models"
                )
