"""RA801-RA803 (``assembler lint --target mjwarp``): what MuJoCo Warp refuses, and its constraint budget.

The kinds are those ``mujoco_warp.put_model`` (4.0.0) raises ``NotImplementedError`` for; its own
enums (``mujoco_warp/_src/types.py``) list what it has, and tests/tools/test_gpu_lint.py keeps these
tables equal to them. MuJoCo refuses a ``distance`` equality itself, so it never reaches an engine.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco
import numpy as np

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.gpu.engines import (
    KindTable,
    flag_names,
    option_finding,
    refused_elements,
    refused_solver_and_enable_flags,
)

WARP_ELEMENT_KINDS: tuple[KindTable, ...] = (
    KindTable("actuator_trntype", "mjtTrn", ("mjTRN_SO3",)),
    KindTable("actuator_dyntype", "mjtDyn", ("mjDYN_PID",)),
    KindTable("actuator_gaintype", "mjtGain", ("mjGAIN_PID",)),
    KindTable("actuator_biastype", "mjtBias", ("mjBIAS_SO3",)),
    KindTable("eq_type", "mjtEq", ("mjEQ_FLEXVERT", "mjEQ_DISTANCE")),
    KindTable("sensor_type", "mjtSensor", ("mjSENS_PLUGIN",)),
)
"""Element kinds MuJoCo Warp has no implementation of (MuJoCo 4.0's PID and SO3 actuators, plugin sensors)."""

WARP_SOLVERS_REFUSED: tuple[str, ...] = ("mjSOL_PGS",)
WARP_ENABLE_REFUSED: tuple[str, ...] = (
    "mjENBL_OVERRIDE",
    "mjENBL_FWDINV",
    "mjENBL_DIAGEXACT",
    "mjENBL_IPC",
    "mjENBL_SPECULATIVE",
)
WARP_DISABLE_REFUSED: tuple[str, ...] = ("mjDSBL_MIDPHASE", "mjDSBL_AUTORESET")

WARP_DENSE_NV_MAX = 60
"""MuJoCo Warp refuses ``jacobian="dense"`` above this many degrees of freedom."""

PLUGIN_FIELDS: tuple[tuple[str, str], ...] = (
    ("body_plugin", "body"),
    ("actuator_plugin", "actuator"),
    ("sensor_plugin", "sensor"),
)

ELEMENT_FIX = {
    "actuator": "use a <motor>, <position>, <velocity> or <general> actuator with gains MuJoCo Warp has",
    "eq": "express the constraint as a connect, weld, joint or tendon equality",
    "sensor": "drop the sensor and compute the quantity from qpos/qvel in your environment",
}


def warp_refused_options(target: LintTarget) -> Iterator[Finding]:
    """RA801 (error): a solver, flag or Jacobian setting MuJoCo Warp's put_model refuses."""
    option = target.model.opt
    yield from refused_solver_and_enable_flags(
        target, "RA801", "mjwarp", WARP_SOLVERS_REFUSED, WARP_ENABLE_REFUSED
    )
    for name in flag_names(int(option.disableflags), "mjtDisableBit", WARP_DISABLE_REFUSED):
        flag = name.removeprefix("mjDSBL_").lower()
        yield option_finding(
            target,
            "RA801",
            "mjwarp",
            f"disable flag {name}",
            f'remove <flag {flag}="disable"/> from <option>',
        )
    dense = int(option.jacobian) == int(mujoco.mjtJacobian.mjJAC_DENSE)
    if dense and target.model.nv > WARP_DENSE_NV_MAX:
        yield option_finding(
            target,
            "RA801",
            "mjwarp",
            f'jacobian="dense" with nv={target.model.nv} (more than {WARP_DENSE_NV_MAX})',
            'set <option jacobian="auto"/> (sparse above 60 dofs)',
        )


def warp_refused_elements(target: LintTarget) -> Iterator[Finding]:
    """RA802 (error): an actuator, equality or sensor kind, or a plugin, MuJoCo Warp's put_model refuses."""
    for table in WARP_ELEMENT_KINDS:
        fix = ELEMENT_FIX[table.field.split("_")[0]]
        yield from refused_elements(target, table, "RA802", "mjwarp", fix)
    for field, word in PLUGIN_FIELDS:
        kind = getattr(mujoco.mjtObj, f"mjOBJ_{word.upper()}")
        for index in np.flatnonzero(getattr(target.model, field) != -1):
            yield Finding(
                code="RA802",
                severity="error",
                subject=target.element_name(kind, int(index)),
                why=f"{word} with a plugin: MuJoCo Warp's put_model refuses plugins (NotImplementedError)",
                fix="replace the plugin with a built-in element (a PID plugin: a <position> actuator "
                "with kp and kv)",
                location=None,
            )


SIZES = tuple(int(s) for s in (2 + np.arange(19) % 2) * 2 ** (np.arange(19) // 2 + 3))
"""The sizes MuJoCo Warp rounds its default njmax up to: 16, 24, 32, 48, ... 8192."""

EQUALITY_ROWS = {"mjEQ_CONNECT": 3, "mjEQ_WELD": 6, "mjEQ_JOINT": 1, "mjEQ_TENDON": 1}


def warp_default_njmax(model: mujoco.MjModel) -> int:
    """The ``njmax`` ``mujoco_warp.make_data`` allocates when not told: its heuristic, without a data."""
    sdf = bool((model.geom_type == mujoco.mjtGeom.mjGEOM_SDF).any())
    guess = max(model.nv * 2.26 * (model.nhfield > 0) * 18 + 53, 512 * (model.nflex > 0), 256 * sdf)
    return int(guess) if guess > SIZES[-1] else next(size for size in SIZES if size >= guess)


def rows_before_contact(model: mujoco.MjModel) -> dict[str, int]:
    """Constraint rows that can all be active with no contact: equalities, friction loss, limits."""
    equality = sum(EQUALITY_ROWS.get(mujoco.mjtEq(int(kind)).name, 0) for kind in model.eq_type)
    friction = int(np.count_nonzero(model.dof_frictionloss > 0))
    friction += int(np.count_nonzero(model.tendon_frictionloss > 0))
    limits = int(np.count_nonzero(model.jnt_limited)) + int(np.count_nonzero(model.tendon_limited))
    return {"equality": equality, "friction loss": friction, "limit": limits}


def rows_per_contact(model: mujoco.MjModel) -> int:
    """Rows of one contact of the largest condim: 2(condim-1) in a pyramidal cone, condim in an elliptic."""
    condim = int(max(model.geom_condim.max(initial=1), model.pair_dim.max(initial=1)))
    if condim == 1 or int(model.opt.cone) == int(mujoco.mjtCone.mjCONE_ELLIPTIC):
        return condim
    return 2 * (condim - 1)


def warp_constraint_budget(target: LintTarget) -> Iterator[Finding]:
    """RA803: constraint rows against MuJoCo Warp's default njmax (warning when they exceed it, else info).

    MuJoCo Warp allocates ``njmax`` rows per world; past it, rows are dropped and the world's
    ``overflow`` flag says NEFC, while the simulation goes on without those constraints.
    """
    model = target.model
    rows = rows_before_contact(model)
    total, per_contact, default = sum(rows.values()), rows_per_contact(model), warp_default_njmax(model)
    counts = ", ".join(f"{count} {kind}" for kind, count in rows.items() if count) or "none"
    advice = total + 8 * per_contact
    if total > default:
        yield Finding(
            code="RA803",
            severity="warning",
            subject=target.name,
            why=(
                f"up to {total} constraint rows before any contact ({counts}), more than the njmax of "
                f"{default} MuJoCo Warp allocates by default: rows past njmax are dropped (nefc overflow)"
            ),
            fix=(
                f"pass njmax={advice} (the rows, plus {per_contact} per contact for 8 contacts) or more to "
                "mujoco_warp.make_data/put_data (mjlab: SimulationCfg(njmax=...))"
            ),
        )
        return
    room = (default - total) // per_contact
    yield Finding(
        code="RA803",
        severity="info",
        subject=target.name,
        why=(
            f"up to {total} constraint rows before any contact ({counts}) and {per_contact} per contact: "
            f"MuJoCo Warp's default njmax of {default} leaves room for {room} contacts per world"
        ),
        fix=(
            f"with more contacts per world (feet, a grasped object, a cluttered table), pass njmax={total} "
            f"+ {per_contact} x contacts to mujoco_warp.make_data/put_data (mjlab: SimulationCfg)"
        ),
    )
