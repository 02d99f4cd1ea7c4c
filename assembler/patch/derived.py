"""The constants MuJoCo derives from the fields a patch writes, recomputed as its compiler does.

``mj_setConst`` recomputes most (subtree masses, inverse weights, ``actuator_acc0``, ...). What it
leaves is done here: a position actuator's ``dampratio`` (the compiler turns it into ``biasprm[2]``
once, from the inertia at qpos0; MuJoCo 3.9 and 4.0 use different inertias, so the rule is read off
the compiled robot), the home keyframe's controls, and the statistics the solvers read.
"""

from __future__ import annotations

import copy

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.mjcf.keyframe import home_control
from assembler.models import RobotModel
from assembler.patch.patchable import ModelPatch, model_patch
from assembler.patch.resolved import Resolved


def _reflected_inertias(
    model: mujoco.MjModel, data: mujoco.MjData, actuators: list[int]
) -> dict[str, NDArray[np.float64]]:
    """Per actuator, the two inertias MuJoCo's compilers have used for a dampratio: the diagonal of the
    inertia matrix at qpos0 (``dof_M0``, MuJoCo 3.9) and ``1 / (M^-1)_ii`` (MuJoCo 4.0), over gear^2."""
    data.qpos[:] = model.qpos0
    mujoco.mj_forward(model, data)  # at qpos0: the inertia matrix and its factorization
    dofs = model.jnt_dofadr[model.actuator_trnid[actuators, 0]]
    units = np.zeros((len(actuators), model.nv))
    units[np.arange(len(actuators)), dofs] = 1.0
    solved = np.zeros_like(units)
    mujoco.mj_solveM(model, data, solved, units)
    gear2 = model.actuator_gear[actuators, 0] ** 2
    return {
        "diagonal": model.dof_M0[dofs] / gear2,
        "inverse": 1.0 / (gear2 * solved[np.arange(len(actuators)), dofs]),
    }


def dampratio_rule(model: mujoco.MjModel, ratios: dict[int, float]) -> str:
    """Which inertia this MuJoCo's compiler used for the dampratios of ``model`` (as compiled): the
    rule whose damping reproduces the compiled ``biasprm[2]``."""
    if not ratios:
        return "inverse"
    actuators = sorted(ratios)
    inertias = _reflected_inertias(model, mujoco.MjData(model), actuators)
    compiled = model.actuator_biasprm[actuators, 2]
    kp, ratio = model.actuator_gainprm[actuators, 0], np.array([ratios[a] for a in actuators])
    errors = {
        rule: np.abs(-ratio * 2 * np.sqrt(kp * inertia) - compiled).max()
        for rule, inertia in inertias.items()
    }
    return min(errors, key=errors.__getitem__)


def resolve_dampratios(
    model: mujoco.MjModel, data: mujoco.MjData, ratios: dict[int, float], rule: str
) -> None:
    """Give each actuator the ``biasprm[2]`` MuJoCo's compiler gives a ``dampratio``: the ratio times
    the critical damping of the inertia its joint reflects at qpos0 (by ``rule``)."""
    if not ratios:
        return
    actuators = sorted(ratios)
    inertia = _reflected_inertias(model, data, actuators)[rule]
    kp, ratio = model.actuator_gainprm[actuators, 0], np.array([ratios[a] for a in actuators])
    model.actuator_biasprm[actuators, 2] = -ratio * 2.0 * np.sqrt(kp * inertia)


def apply_patch(model: mujoco.MjModel, patch: ModelPatch, data: mujoco.MjData | None = None) -> None:
    """Write ``patch`` into ``model`` (a copy you own) and recompute what MuJoCo derives from it
    (``data``: scratch data of ``model``, made when not given; its state is overwritten)."""
    data = mujoco.MjData(model) if data is None else data
    rule = patch.dampratio_rule or dampratio_rule(model, patch.dampratio)  # off the unpatched model
    for name, row, value in patch.entries:
        getattr(model, name)[row] = value
    mujoco.mj_setConst(model, data)
    resolve_dampratios(model, data, patch.dampratio, rule)
    # The compiler's statistics that physics reads (the solvers scale by meaninertia); mj_setConst
    # leaves them. extent, center and meansize (drawing only) keep the compiled robot's values.
    if model.nv:
        model.stat.meaninertia = float(np.mean(model.dof_M0))
    if model.nbody > 1:
        model.stat.meanmass = float(np.mean(model.body_mass[1:]))
    # The home controls hold the home pose: new ones when the pose, a gain or a control range changes
    # (a dampratio's biasprm[2] is not read by them).
    holding = {"key_qpos", "actuator_gainprm", "actuator_ctrlrange"}
    bias = any(name == "actuator_biasprm" and row not in patch.dampratio for name, row, _ in patch.entries)
    if model.nkey and model.nu and (bias or holding & set(patch.fields)):
        home = model.key("home").id
        model.key_ctrl[home] = home_control(model, model.key_qpos[home])


def patched_model(model: mujoco.MjModel, base: RobotModel, variant: RobotModel) -> mujoco.MjModel:
    """A copy of ``model`` (the compiled ``base``) patched into the compiled ``variant``."""
    patch = model_patch(model, Resolved.of(base), Resolved.of(variant))
    patched = copy.copy(model)  # MuJoCo's mj_copyModel: its own arrays
    apply_patch(patched, patch)
    return patched
