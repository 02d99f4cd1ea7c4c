"""A variant plan as one batch of MuJoCo Warp worlds: compiled once, each world's values in arrays.

The plan is validated once and each varied field's effect on the compiled model probed once
(:mod:`assembler.warp.plan_effects`); every world's values are then arrays, given to ``put_model``
as per-world fields (``batch_sizes``), with the constants MuJoCo derives from them recomputed on the
device (``mujoco_warp.set_const``, and the dampratios). A plan whose fields do not fit those laws is
patched world by world on CPU (:mod:`assembler.warp.world_values`), as the CPU patch does it; either
way each world equals its ``assemble(robot, overrides=...)`` model. :meth:`WarpBatch.resample`
draws new values for some worlds and writes them into the model in place. Each world starts at its
robot's home pose.
"""

from __future__ import annotations

import dataclasses
import json
import logging
from collections.abc import Sequence
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.compiler.keyframe import HOME_KEY
from assembler.models import RobotModel
from assembler.registry.instances import assemble
from assembler.spec.documents import Override, parse_overrides, parse_path
from assembler.warp.device import resolve_dampratios, write_rows
from assembler.warp.loading import mujoco_warp, warp_types
from assembler.warp.plan_effects import NoEffects, PlanEffects, plan_effects
from assembler.warp.seeded_draws import plan_columns
from assembler.warp.world_values import (
    SET_CONST_ONLY,
    SET_CONST_OUTPUTS,
    home_controls,
    nominal_fields,
    refuse_field,
    world_patches,
    world_values,
)
from assembler.worlds.variants.plan import VariantPlan

LOG = logging.getLogger("assembler.warp.batch")

Columns = tuple[dict[str, NDArray[np.int64]], dict[str, NDArray[np.float64]]]
"""Grid positions and drawn values of some worlds (:meth:`VariantPlan.columns`)."""

NO_DERIVED = frozenset(
    {
        "dof_damping",
        "dof_frictionloss",
        "jnt_stiffness",
        "geom_friction",
        "actuator_gainprm",
        "actuator_biasprm",
    }
    | {"actuator_ctrlrange", "actuator_forcerange", "key_qpos"}
)
"""Fields nothing ``set_const`` computes reads: a plan varying only these needs no ``set_const``."""


def model_fields() -> set[str]:
    """Every field of ``mujoco_warp.Model``."""
    return {f.name for f in dataclasses.fields(warp_types.Model)}


def batchable_fields() -> set[str]:
    """The ``mujoco_warp.Model`` fields that may hold one value per world (their shape starts with '*')."""
    fields = dataclasses.fields(warp_types.Model)
    return {f.name for f in fields if getattr(f.type, "shape", ())[:1] == ("*",)}


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


@dataclass
class Rows:
    """Some worlds' values: per written field one row per world, and each world's home state."""

    values: dict[str, NDArray[np.float64]]
    qpos: NDArray[np.float64]
    ctrl: NDArray[np.float64]


@dataclass
class WarpBatch:
    """One MuJoCo Warp world per variant of a plan."""

    model: Any
    """The ``mujoco_warp.Model``: the fields in ``varied`` hold one row per world."""

    data: Any
    """The ``mujoco_warp.Data`` with ``nworld`` worlds, each at its robot's home pose."""

    plan: VariantPlan
    """The plan; world i is its variant i, drawn with the seed ``seeds[i]``."""

    varied: list[str]
    """The model fields given per-world values, derived constants included."""

    cpu_model: mujoco.MjModel
    """The robot compiled once (the plan's fixed overrides applied): every world's shared values."""

    robot: RobotModel
    """The robot ``cpu_model`` was compiled from."""

    effects: PlanEffects | None
    """The laws giving every world's values (None: each world is patched on CPU, see the module)."""

    nominal: dict[str, str] = field(default_factory=dict)
    """Derived fields that differ between the worlds on CPU but keep the robot's value in every
    MuJoCo Warp world -> why that is harmless (``dof_length`` under a size_scale)."""

    seeds: NDArray[np.int64] = field(default_factory=lambda: np.zeros(0, dtype=np.int64))
    """Each world's draw seed: the plan's, then the one :meth:`resample` last drew it with."""

    @property
    def nworld(self) -> int:
        """Number of worlds."""
        return len(self.seeds)

    def variant(self, world: int) -> dict[str, Any]:
        """World ``world``'s varied values, as :meth:`VariantPlan.variant` gives them."""
        return dataclasses.replace(self.plan, seed=int(self.seeds[world])).variant(world)

    def world_overrides(self, world: int) -> list[str]:
        """World ``world``'s ``PATH=VALUE`` overrides (the plan's ``--set`` first), for ``assemble``."""
        return override_texts(self.plan, self.variant(world))

    @property
    def overrides(self) -> list[list[str]]:
        """Every world's :meth:`world_overrides`, made when asked (after :meth:`resample`: its draws)."""
        return [self.world_overrides(world) for world in range(self.nworld)]

    def resample(self, worlds: Sequence[int] | NDArray[np.int64], seed: int) -> None:
        """Draw new values for ``worlds`` (the plan's draws with ``seed``; each world keeps its grid
        point) and write them into ``model`` in place, derived constants and dampratios recomputed on
        the device: no compile, no copy of the model through the host. The worlds' state (``data``) is
        left as it is: reset it as your task does (mjlab's reset events run after this one)."""
        indices = np.asarray(worlds, dtype=np.int64)
        if indices.size == 0:
            return
        plan = dataclasses.replace(self.plan, seed=seed)
        rows = world_rows(plan, self.robot, self.cpu_model, self.effects, indices)
        for name in self.varied:
            if name in rows.values:
                write_rows(getattr(self.model, name), indices, rows.values[name])
            elif name not in SET_CONST_OUTPUTS:  # patched on CPU, no world writes it: the robot's value
                nominal = np.asarray(getattr(self.cpu_model, name), dtype=float)
                write_rows(
                    getattr(self.model, name), indices, np.tile(nominal.reshape(1, -1), (len(indices), 1))
                )
        _derive(self.model, self.data, self.effects, self.cpu_model, set(rows.values), restore=True)
        self.seeds[indices] = seed


def world_rows(
    plan: VariantPlan,
    robot: RobotModel,
    model: mujoco.MjModel,
    effects: PlanEffects | None,
    indices: NDArray[np.int64],
    columns: Columns | None = None,
) -> Rows:
    """The values of the plan's worlds ``indices`` (``columns``: theirs, when drawn already): by the
    plan's laws, or patched one by one."""
    home = model.key(HOME_KEY).id if model.nkey else None
    if effects is None:
        variants = list(plan.variants(int(i) for i in indices))
        labels = [
            f"world {i} ({', '.join(override_texts(plan, v)[len(plan.fixed) :])})"
            for i, v in zip(indices, variants, strict=True)
        ]
        patches = world_patches(robot, model, variant_items(plan, variants), labels)
        written = sorted({name for patch in patches for name in patch.fields} | set(SET_CONST_OUTPUTS))
        found = world_values(model, patches, [n for n in written if hasattr(model, n)])
        return Rows(found.values, found.qpos, found.ctrl)
    positions, drawn = columns if columns is not None else plan_columns(plan, [int(i) for i in indices])
    effects.validate(drawn)
    values = effects.arrays(positions, drawn, len(indices))
    qpos = values["key_qpos"][:, home] if "key_qpos" in values and home is not None else None
    if qpos is None:
        qpos = np.repeat(
            (model.key_qpos[home] if home is not None else model.qpos0)[None], len(indices), axis=0
        )
    holding = {"key_qpos", "actuator_gainprm", "actuator_biasprm", "actuator_ctrlrange"}
    if home is not None and holding & set(values):
        ctrl = home_controls(model, qpos, values)
    else:
        ctrl = np.repeat(
            (model.key_ctrl[home] if home is not None else np.zeros(model.nu))[None], len(indices), axis=0
        )
    return Rows(values, qpos, ctrl)


def _derive(
    model: Any, data: Any, effects: PlanEffects | None, cpu: mujoco.MjModel, written: set[str], restore: bool
) -> None:
    """Recompute on the device the constants MuJoCo derives from ``written`` fields."""
    if written - NO_DERIVED:
        mujoco_warp.set_const(model, data, restore=restore)
    if effects is not None and written:
        dofs = {a: int(cpu.jnt_dofadr[cpu.actuator_trnid[a, 0]]) for a in effects.dampratio}
        resolve_dampratios(model, effects.dampratio, dofs)


def laws_of(
    plan: VariantPlan, robot: RobotModel, model: mujoco.MjModel, columns: Columns
) -> PlanEffects | None:
    """The plan's laws, or None (logged) when its worlds must be patched one by one."""
    positions, drawn = columns
    try:
        effects = plan_effects(plan, robot, model, positions, drawn)
    except NoEffects as reason:
        LOG.debug("%s: each world patched on CPU: %s", plan.robot, reason)
        return None
    if effects.dampratio and effects.rule != "inverse":
        varying = {name for name, laws in effects.fields.items() if laws.sets or laws.tables or laws.scales}
        if varying <= NO_DERIVED - {"actuator_gainprm", "actuator_biasprm"}:
            effects.dampratio = {}  # nothing a dampratio reads varies: each keeps the compiled biasprm[2]
            return effects
        LOG.debug("%s: each world patched on CPU: dampratios by this MuJoCo's diagonal rule", plan.robot)
        return None
    return effects


def put_variants(plan: VariantPlan, nconmax: int | None = None, njmax: int | None = None) -> WarpBatch:
    """The plan's variants (the grids and seeded draws of ``assembler variants``) as MuJoCo Warp worlds,
    from one compile. A variant that changes what a world cannot vary (a count, a type, mesh data, a
    sensor zone's size) is refused with one line naming the world and the field."""
    plan.check()
    grippers = dict(plan.grippers)
    robot: RobotModel = assemble(plan.robot, plan.idn, plan.base, grippers, overrides=list(plan.fixed))
    model = robot.get_model(cache=plan.cache, store=plan.store)
    indices = np.arange(plan.size, dtype=np.int64)
    columns = plan_columns(plan, range(plan.size))
    effects = laws_of(plan, robot, model, columns)
    rows = world_rows(plan, robot, model, effects, indices, columns)
    fields, batchable = model_fields(), batchable_fields()
    nominal = checked_worlds(plan, robot, model, rows, fields, batchable)
    written = {name for name in rows.values if name in batchable and _varies(rows.values[name], model, name)}
    derived = {f for f in SET_CONST_OUTPUTS if f in batchable} if written else set()
    if effects is not None and effects.dampratio and written:
        derived.add("actuator_biasprm")
    varied = sorted(written | derived)
    nworld = plan.size
    warp_model = mujoco_warp.put_model(model, batch_sizes={name: nworld for name in varied})
    for name in written:  # uploaded and written on the device: nothing of the model is read back
        write_rows(getattr(warp_model, name), indices, rows.values[name])
    warp_data = home_data(model, nworld, nconmax, njmax)
    _derive(warp_model, warp_data, effects, model, written, restore=False)
    warp_data.qpos.assign(rows.qpos.astype(np.float32))
    warp_data.ctrl.assign(rows.ctrl.astype(np.float32))
    mujoco_warp.forward(warp_model, warp_data)
    seeds = np.full(nworld, plan.seed, dtype=np.int64)
    return WarpBatch(warp_model, warp_data, plan, varied, model, robot, effects, nominal, seeds)


def home_data(model: mujoco.MjModel, nworld: int, nconmax: int | None, njmax: int | None) -> Any:
    """``nworld`` worlds of ``model`` in its home keyframe's state (each world's qpos and ctrl are
    written next), made on the device: ``put_data`` of a host ``MjData`` tiles every array, the
    constraint buffers too, once per world (0.19-0.29 s for 4,096 Sparrow7 worlds on CPU, against
    0.02-0.12 s). The buffers are sized as ``put_data`` sizes them: MuJoCo Warp's guess, raised to
    the home pose's own contacts and constraints."""
    home = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, home, mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY))
    mujoco.mj_forward(model, home)
    data = mujoco_warp.make_data(model, nworld=nworld, nconmax=nconmax, njmax=njmax)
    if nconmax is None and data.naconmax < home.ncon * nworld or njmax is None and data.njmax < home.nefc:
        nconmax = max(home.ncon, data.naconmax // nworld) if nconmax is None else nconmax
        njmax = max(home.nefc, data.njmax) if njmax is None else njmax
        data = mujoco_warp.make_data(model, nworld=nworld, nconmax=nconmax, njmax=njmax)
    for name in ("qvel", "act", "mocap_pos", "mocap_quat"):  # make_data starts at rest at qpos0
        value = getattr(home, name)
        if value.size and value.any():
            getattr(data, name).assign(np.repeat(value[None], nworld, axis=0).astype(np.float32))
    if home.time:
        data.time.assign(np.full(nworld, home.time, dtype=np.float32))
    return data


def _varies(values: NDArray[np.float64], model: mujoco.MjModel, name: str) -> bool:
    """Whether a field's rows differ between the worlds or from the compiled robot's value."""
    ours = np.asarray(getattr(model, name), dtype=float)
    return bool((values != values[:1]).any() or not np.array_equal(values[0].reshape(ours.shape), ours))


def checked_worlds(
    plan: VariantPlan,
    robot: RobotModel,
    model: mujoco.MjModel,
    rows: Rows,
    fields: set[str],
    batchable: set[str],
) -> dict[str, str]:
    """Refuse what the worlds vary that MuJoCo Warp cannot vary (naming a world and the field), and list
    the derived fields that may keep the robot's value; with the laws, world 0's and the last world's
    values are checked against the CPU patch of each (a wrong law is a bug: it crashes)."""
    varying = [n for n, v in rows.values.items() if n in fields and _varies(v, model, n)]
    for name in varying:
        if name not in batchable:
            world = int(
                np.argmax(
                    (rows.values[name] != rows.values[name][:1]).reshape(len(rows.qpos), -1).any(axis=1)
                )
            )
            texts = override_texts(plan, plan.variant(world))[len(plan.fixed) :]
            refuse_field(name, fields, batchable, f"world {world} ({', '.join(texts)})")
    ends = sorted({0, plan.size - 1})
    variants = [plan.variant(i) for i in ends]
    patches = world_patches(robot, model, variant_items(plan, variants), [f"world {i}" for i in ends])
    extra = [n for n in SET_CONST_ONLY if hasattr(model, n) and n in fields]
    exact = world_values(model, patches, sorted({n for n in rows.values if hasattr(model, n)} | set(extra)))
    for row, world in enumerate(ends):
        for name, values in rows.values.items():
            if name in fields and name not in SET_CONST_OUTPUTS and not name.startswith("actuator_biasprm"):
                expected = exact.values[name][row]
                if not np.allclose(values[world].reshape(expected.shape), expected, rtol=1e-9, atol=1e-12):
                    raise AssertionError(f"world {world}: {name} by the plan's laws is not the CPU patch's")
    return nominal_fields(model, {n: exact.values[n] for n in extra}, fields, batchable, f"world {ends[-1]}")
