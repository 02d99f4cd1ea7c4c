"""A variant plan as one batch of MuJoCo Warp worlds: compiled once, each world patched.

``put_model`` gets per-world arrays (``batch_sizes``) for every field some world varies and for
the constants MuJoCo derives from them; each row is that world's value as the CPU patch gives it
(equal to a full compile, :mod:`assembler.patch.patchable`); then ``mujoco_warp.set_const``
recomputes the derived constants on the device. Each world starts at its robot's home pose.
"""

from __future__ import annotations

import dataclasses
import json
from dataclasses import dataclass
from typing import Any

import mujoco
import numpy as np

from assembler.mjcf.keyframe import HOME_KEY
from assembler.models import RobotModel
from assembler.registry.instances import assemble
from assembler.spec.documents import Override, parse_overrides, parse_path
from assembler.warp.loading import mujoco_warp, warp_types
from assembler.warp.world_values import SET_CONST_OUTPUTS, refused_fields, world_patches, world_values
from assembler.worlds.variants.plan import VariantPlan


def model_fields() -> set[str]:
    """Every field of ``mujoco_warp.Model``."""
    return {f.name for f in dataclasses.fields(warp_types.Model)}


def batchable_fields() -> set[str]:
    """The ``mujoco_warp.Model`` fields that may hold one value per world (their shape starts with '*')."""
    fields = dataclasses.fields(warp_types.Model)
    return {f.name for f in fields if getattr(f.type, "shape", ())[:1] == ("*",)}


@dataclass
class WarpBatch:
    """One MuJoCo Warp world per variant of a plan."""

    model: Any
    """The ``mujoco_warp.Model``: the fields in ``varied`` hold one row per world."""

    data: Any
    """The ``mujoco_warp.Data`` with ``nworld`` worlds, each at its robot's home pose."""

    overrides: list[list[str]]
    """Each world's ``PATH=VALUE`` overrides (the plan's ``--set`` first), as ``assemble`` takes them."""

    varied: list[str]
    """The model fields given per-world values, derived constants included."""

    cpu_model: mujoco.MjModel
    """The robot compiled once (the plan's fixed overrides applied): every world's shared values."""

    @property
    def nworld(self) -> int:
        """Number of worlds."""
        return len(self.overrides)


def override_texts(plan: VariantPlan, variant: dict[str, Any]) -> list[str]:
    """A variant's overrides as ``PATH=VALUE`` texts: the plan's ``--set`` ones, then its own."""
    chosen = [f"{key}={json.dumps(value)}" for key, value in variant.items()]
    return [*plan.fixed, *chosen]


def variant_items(plan: VariantPlan, variants: list[dict[str, Any]]) -> list[list[Override]]:
    """Each variant's overrides, parsed: the plan's fixed ones once, the chosen values as they are
    (the values a plan draws are numbers already; nothing is read back from text)."""
    fixed = parse_overrides(plan.fixed, "--set ")
    paths = {key: parse_path(key) for key in plan.varied()}
    flags = {key: plan.flag_of(key) + " " for key in plan.varied()}
    return [[*fixed, *(Override(paths[k], v, flags[k]) for k, v in variant.items())] for variant in variants]


def put_variants(plan: VariantPlan, nconmax: int | None = None, njmax: int | None = None) -> WarpBatch:
    """The plan's variants (the grids and seeded draws of ``assembler variants``) as MuJoCo Warp worlds,
    from one compile. A variant that changes what a world cannot vary (a count, a type, mesh data,
    site sizes) is refused with one line naming the world and the field."""
    plan.check()
    grippers = dict(plan.grippers)
    robot: RobotModel = assemble(plan.robot, plan.idn, plan.base, grippers, overrides=list(plan.fixed))
    model = robot.get_model(cache=plan.cache, store=plan.store)
    variants = plan.variant_overrides()
    texts = [override_texts(plan, variant) for variant in variants]
    labels = [f"world {i} ({', '.join(t[len(plan.fixed) :])})" for i, t in enumerate(texts)]
    items = variant_items(plan, variants)
    patches = world_patches(robot, model, items, labels)
    batchable = batchable_fields()
    refused_fields(patches, model_fields(), batchable, labels)
    written = {name for patch in patches for name in patch.fields if name in batchable}
    varied = sorted(written | ({f for f in SET_CONST_OUTPUTS if f in batchable} if written else set()))
    values = world_values(model, patches, varied)
    nworld = len(variants)
    warp_model = mujoco_warp.put_model(model, batch_sizes={name: nworld for name in varied})
    for name in varied:
        target = getattr(warp_model, name)
        shape = target.numpy().shape
        target.assign(values.values[name].reshape(shape).astype(target.numpy().dtype))
    home = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, home, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY))
    mujoco.mj_forward(model, home)
    warp_data = mujoco_warp.put_data(model, home, nworld=nworld, nconmax=nconmax, njmax=njmax)
    if varied:
        mujoco_warp.set_const(warp_model, warp_data)
    warp_data.qpos.assign(values.qpos.astype(np.float32))
    warp_data.ctrl.assign(values.ctrl.astype(np.float32))
    mujoco_warp.forward(warp_model, warp_data)
    return WarpBatch(warp_model, warp_data, texts, varied, model)
