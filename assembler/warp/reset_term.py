"""A variant plan re-drawn at every reset of an mjlab task: an event term, with no mjlab import.

mjlab's ``EventTermCfg(func=term, mode="reset")`` calls ``term(env, env_ids)`` with the environments
being reset, and gives one value per world to the model fields the term lists in ``model_fields``
(``Simulation.expand_model_fields`` at startup). :class:`ResampleAtReset` is such a term: at each
call it draws the plan's values for those environments with a new seed (environment i is the plan's
variant ``i % plan.size``: its grid point, new draws), computes them as ``put_variants`` does
(:mod:`assembler.warp.plan_effects`), writes them into mjlab's MuJoCo Warp model in place on its
device (the robot's elements found by name under the entity's prefix, ``robot/``) and recomputes
the derived constants there (``mujoco_warp.set_const``, the dampratios). Nothing is compiled and the
model never goes through the host. Only the asset's own elements are written: a scene's floor or
other entities keep their values.
"""

from __future__ import annotations

import dataclasses
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import AssemblerError
from assembler.models import RobotModel
from assembler.registry.instances import assemble
from assembler.warp.batch import batchable_fields, laws_of, world_rows
from assembler.warp.device import resolve_dampratios, write_rows
from assembler.warp.loading import mujoco_warp
from assembler.warp.plan_effects import NoEffects, plan_effects
from assembler.warp.seeded_draws import plan_columns
from assembler.warp.world_values import SET_CONST_OUTPUTS
from assembler.worlds.variants.plan import VariantPlan

KINDS: dict[str, mujoco.mjtObj] = {
    "body": mujoco.mjtObj.mjOBJ_BODY,
    "geom": mujoco.mjtObj.mjOBJ_GEOM,
    "site": mujoco.mjtObj.mjOBJ_SITE,
    "jnt": mujoco.mjtObj.mjOBJ_JOINT,
    "actuator": mujoco.mjtObj.mjOBJ_ACTUATOR,
    "cam": mujoco.mjtObj.mjOBJ_CAMERA,
    "light": mujoco.mjtObj.mjOBJ_LIGHT,
}
"""A model field's first word -> the kind of element its rows are (``dof_`` rows go by joint)."""


def _element_rows(ours: mujoco.MjModel, theirs: mujoco.MjModel, kind: str, prefix: str) -> NDArray[np.int64]:
    """For each row of ``ours`` of one kind, its row in ``theirs`` (``prefix`` + its name), or -1."""
    if kind == "dof":
        rows = np.full(ours.nv, -1, dtype=np.int64)
        joints = _element_rows(ours, theirs, "jnt", prefix)
        for joint, their in enumerate(joints):
            if their >= 0:
                ndof = int(np.sum(ours.dof_jntid == joint))
                first = ours.jnt_dofadr[joint]
                rows[first : first + ndof] = theirs.jnt_dofadr[their] + np.arange(ndof)
        return rows
    obj = KINDS[kind]
    counts = {
        "body": ours.nbody,
        "geom": ours.ngeom,
        "site": ours.nsite,
        "jnt": ours.njnt,
        "actuator": ours.nu,
    }
    count = int((counts | {"cam": ours.ncam, "light": ours.nlight})[kind])
    rows = np.full(count, -1, dtype=np.int64)
    for row in range(count):
        name = mujoco.mj_id2name(ours, obj, row)
        if name:
            rows[row] = mujoco.mj_name2id(theirs, obj, prefix + name)
    if kind == "body":
        rows[0] = 0  # the world
    return rows


def _columns(ours: mujoco.MjModel, theirs: mujoco.MjModel, field: str, prefix: str) -> NDArray[np.int64]:
    """For each number of ``field`` in ``ours`` (flattened), its place in a world's row of ``theirs``."""
    kind = field.split("_")[0]
    if kind != "dof" and kind not in KINDS:
        raise AssemblerError(
            f"{field}: not a field of bodies, geoms, sites, joints, dofs, actuators, cameras or lights"
        )
    rows = _element_rows(ours, theirs, kind, prefix)
    width = int(np.asarray(getattr(ours, field)).reshape(len(rows), -1).shape[1]) if len(rows) else 0
    places = rows[:, None] * width + np.arange(width)
    return np.where(rows[:, None] >= 0, places, -1).reshape(-1)


class ResampleAtReset:
    """An mjlab reset event term re-drawing ``plan`` for the environments being reset (see the module).

    ``EventTermCfg(func=ResampleAtReset(plan), mode="reset")``; ``entity``: the scene entity holding
    the plan's robot (mjlab prefixes its names with ``entity/``); the k-th call draws with seed
    ``seed + k`` (default: the plan's seed + 1, so the first reset already differs from the plan's
    own draws)."""

    def __init__(self, plan: VariantPlan, entity: str = "robot", seed: int | None = None) -> None:
        plan.check()
        self.plan = plan
        self.prefix = f"{entity}/"
        self.seed = plan.seed + 1 if seed is None else seed
        self.calls = 0
        self.robot: RobotModel = assemble(
            plan.robot, plan.idn, plan.base, dict(plan.grippers), overrides=list(plan.fixed)
        )
        self.model = self.robot.get_model(cache=plan.cache, store=plan.store)
        self.effects = laws_of(plan, self.robot, self.model, plan_columns(plan, range(plan.size)))
        written = self._written()
        derived = [name for name in SET_CONST_OUTPUTS if name in batchable_fields()]
        if self.effects is not None and self.effects.dampratio:
            derived.append("actuator_biasprm")
        self.model_fields: tuple[str, ...] = tuple(sorted({*written, *derived}))
        """The fields mjlab gives one value per world (it reads this attribute of an event term)."""
        self._maps: dict[str, NDArray[np.int64]] | None = None

    def __deepcopy__(self, memo: dict[int, Any]) -> ResampleAtReset:
        """Itself: mjlab copies its configs, and the term holds a compiled robot (a spec Python
        cannot copy) and its calls' count, which one task shares."""
        return self

    def _written(self) -> list[str]:
        """The batchable model fields the plan's values write: the laws' fields (probed even where this
        MuJoCo's dampratio rule has every world patched on CPU), else those of every world's patch."""
        batchable = batchable_fields()
        columns = plan_columns(self.plan, range(self.plan.size))
        try:
            probed = plan_effects(self.plan, self.robot, self.model, *columns)
        except NoEffects:
            rows = world_rows(self.plan, self.robot, self.model, None, np.arange(self.plan.size))
            return sorted(name for name in rows.values if name in batchable and name not in SET_CONST_OUTPUTS)
        return sorted(name for name in probed.fields if name in batchable)

    def __call__(self, env: Any, env_ids: Any = None) -> None:
        sim = env.sim
        worlds = np.arange(env.num_envs) if env_ids is None else np.asarray(env_ids.cpu(), dtype=np.int64)
        if worlds.size == 0:
            return
        theirs = sim.mj_model
        if self._maps is None:
            self._maps = {name: _columns(self.model, theirs, name, self.prefix) for name in self._written()}
        plan = dataclasses.replace(self.plan, seed=self.seed + self.calls)
        self.calls += 1
        rows = world_rows(plan, self.robot, self.model, self.effects, worlds % plan.size)
        for name, columns in self._maps.items():
            target = getattr(sim.wp_model, name)
            if target.shape[0] != env.num_envs:
                raise AssemblerError(
                    f"{name}: mjlab did not expand it per world; list it in the term's model_fields"
                )
            kept = columns >= 0
            found = rows.values.get(name)  # a world patched on CPU writes only what differs
            nominal = np.asarray(getattr(self.model, name)).reshape(-1)
            values = np.tile(nominal, (len(worlds), 1)) if found is None else found.reshape(len(worlds), -1)
            if (values[:, ~kept] != nominal[~kept]).any():
                raise AssemblerError(
                    f"{name}: the plan varies an element mjlab's model has not under '{self.prefix}'"
                )
            write_rows(target, worlds, values[:, kept], columns[kept])
        mujoco_warp.set_const(sim.wp_model, sim.wp_data)
        if self.effects is not None and self.effects.dampratio:
            actuators = _element_rows(self.model, theirs, "actuator", self.prefix)
            ratios = {int(actuators[a]): r for a, r in self.effects.dampratio.items() if actuators[a] >= 0}
            dofs = {a: int(theirs.jnt_dofadr[theirs.actuator_trnid[a, 0]]) for a in ratios}
            resolve_dampratios(sim.wp_model, ratios, dofs)
