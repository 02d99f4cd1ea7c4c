"""Each world's values of the fields a variant plan varies, from one compiled model patched in turn,
and what MuJoCo Warp may not vary per world.

The exact path (a plan outside :mod:`assembler.warp.plan_effects`' laws, and the check of two worlds
of a plan inside them): every variant is resolved against the robot (a spec validation, no MJCF
preparation), turned into a patch (:mod:`assembler.patch.patchable`), written into one scratch
model, its derived constants recomputed with ``mj_setConst``, and the varied fields read back; then
the scratch model is restored. Nothing is compiled but the robot itself, and no model is copied per
world. :func:`refuse_field` and :func:`nominal_fields` say what a world may not vary on MuJoCo Warp,
and :func:`home_controls` gives the worlds' home controls in arrays.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import AssemblerError
from assembler.models import RobotModel
from assembler.patch.derived import ModelPatch, apply_patch, dampratio_rule
from assembler.patch.patchable import NotPatchable, model_patch
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

NOMINAL: dict[str, str] = {
    "dof_length": "MuJoCo Warp holds one dof_length for all worlds (set_const leaves it); it weights "
    "velocities for sleeping only, so each world keeps the robot's",
}
"""Derived fields MuJoCo Warp cannot vary per world but reads for nothing a world's physics needs
(unless the model sleeps: then a plan changing them is refused): -> why each world keeps the robot's value."""

WHY: dict[str, str] = {
    "site_size": "a touch or contact sensor's zone, whose size follows its body's size_scale",
}
"""Why a variant writes a field, where its name alone does not say."""

SET_CONST_ONLY: tuple[str, ...] = (
    "dof_length",
    "actuator_length0",
    "flexedge_length0",
    "flexedge_invweight0",
)
"""Fields ``mj_setConst`` derives that MuJoCo Warp's ``set_const`` does not (compared between worlds)."""

SLEEP_READS = frozenset({"dof_length"})
"""Of :data:`NOMINAL`, the fields sleeping reads: refused when the model enables sleep."""


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


def refuse_field(name: str, fields: set[str], batchable: set[str], label: str) -> None:
    """One line naming a field a world varies that MuJoCo Warp has (``fields``) but cannot vary per
    world; fields it does not have (``bvh_aabb``, ``dof_M0``) do not reach it."""
    if name in fields and name not in batchable and name not in HOME_FIELDS:
        why = f" ({WHY[name]})" if name in WHY else ""
        raise AssemblerError(
            f"{label}: varies {name}{why}, which MuJoCo Warp cannot vary per world "
            "(fields it can vary start with '*' in mujoco_warp's types.Model); "
            "build such variants as separate models"
        )


def nominal_fields(
    model: mujoco.MjModel,
    derived: dict[str, NDArray[np.float64]],
    fields: set[str],
    batchable: set[str],
    label: str,
) -> dict[str, str]:
    """The derived fields MuJoCo Warp cannot vary that differ between some worlds (``derived``: field ->
    those worlds' rows, the CPU patch's): each listed with why it may keep the robot's value
    (:data:`NOMINAL`), or refused (:func:`refuse_field`)."""
    sleeps = bool(model.opt.enableflags & getattr(mujoco.mjtEnableBit, "mjENBL_SLEEP", 0))
    nominal = {}
    for name, rows in derived.items():
        same = all(np.allclose(row, getattr(model, name), rtol=1e-12, atol=0) for row in rows)
        if not same:
            if name in NOMINAL and not (sleeps and name in SLEEP_READS):
                nominal[name] = NOMINAL[name]
            else:
                refuse_field(name, fields, batchable, label)
    return nominal


def home_controls(
    model: mujoco.MjModel, qpos: NDArray[np.float64], values: dict[str, NDArray[np.float64]]
) -> NDArray[np.float64]:
    """Each world's home controls (``assembler.compiler.keyframe.home_control``, in arrays): its home
    position for a position actuator on a joint (clipped to its control range), 0 for the others;
    ``values``: the worlds' own ``actuator_gainprm``, ``biasprm`` or ``ctrlrange`` where they vary."""
    n = len(qpos)

    def field(name: str) -> NDArray[np.float64]:
        return (
            values[name]
            if name in values
            else np.broadcast_to(getattr(model, name), (n, *getattr(model, name).shape))
        )

    kp, bias1 = field("actuator_gainprm")[:, :, 0], field("actuator_biasprm")[:, :, 1]
    on_joint = model.actuator_trntype == mujoco.mjtTrn.mjTRN_JOINT
    holds = on_joint & (kp > 0) & np.isclose(bias1, -kp)
    joints = np.where(on_joint, model.actuator_trnid[:, 0], 0)
    target = qpos[:, model.jnt_qposadr[joints]]
    ranges = field("actuator_ctrlrange")
    limited = model.actuator_ctrllimited.astype(bool)
    target = np.where(limited, np.clip(target, ranges[:, :, 0], ranges[:, :, 1]), target)
    return np.where(holds, target, 0.0)
