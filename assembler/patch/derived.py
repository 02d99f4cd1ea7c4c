"""A patch of a compiled model: the entries it writes, the constants MuJoCo derives from them
(recomputed as its compiler does), and the patch kept in the cache in place of the model it makes.

``mj_setConst`` recomputes most (subtree masses, inverse weights, ``actuator_acc0``, ...). What it
leaves is done here: a position actuator's ``dampratio`` (the compiler turns it into ``biasprm[2]``
once, from the inertia at qpos0; MuJoCo 3.9 and 4.0 use different inertias, so the rule is read off
the compiled robot), the home keyframe's controls, and the statistics the solvers read.

A variant's model made by a patch is not stored (see :mod:`assembler.patch.robot_variant`), but its
patch is (:func:`keep_patch`): a new process then answers the same request from the plain robot's
entry and the patch (:func:`kept_model`), with no spec read and no schema imported. This module
imports neither, so that answer stays light.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.compiler.keyframe import home_control
from assembler.compiler.stored import default_store, load_entry


@dataclass
class ModelPatch:
    """Entries to write into a compiled model: ``field[row] = value``, then derived constants."""

    entries: list[tuple[str, int, Any]] = field(default_factory=list)
    dampratio: dict[int, float] = field(default_factory=dict)
    """Actuator -> damping ratio: its ``biasprm[2]`` is recomputed after ``mj_setConst``."""

    dampratio_rule: str | None = None
    """How this MuJoCo's compiler resolves a dampratio (``assembler.patch.derived.dampratio_rule``);
    None: read off the model the patch is applied to, before it is patched."""

    def set(self, name: str, row: int, value: Any) -> None:
        """Write ``value`` into row ``row`` of the model field ``name``."""
        self.entries.append((name, row, value))

    @property
    def fields(self) -> list[str]:
        """The model fields this patch writes (before derived constants), each once."""
        return sorted({name for name, _, _ in self.entries})

    def to_data(self) -> dict[str, Any]:
        """The patch as JSON data (floats written in full: :meth:`from_data` gives the same values)."""
        return {
            "entries": [[name, row, np.asarray(value).tolist()] for name, row, value in self.entries],
            "dampratio": [[row, ratio] for row, ratio in self.dampratio.items()],
            "dampratio_rule": self.dampratio_rule,
        }

    @classmethod
    def from_data(cls, data: Mapping[str, Any]) -> ModelPatch:
        """The patch :meth:`to_data` wrote; ValueError for anything else."""
        try:
            entries = [(str(name), int(row), np.asarray(value)) for name, row, value in data["entries"]]
            dampratio = {int(row): float(ratio) for row, ratio in data["dampratio"]}
            rule = data["dampratio_rule"]
        except (KeyError, TypeError, ValueError) as error:
            raise ValueError(f"not a patch: {error}") from None
        if rule not in ("diagonal", "inverse"):
            raise ValueError(f"not a patch: dampratio rule {rule!r}")
        return cls(entries, dampratio, rule)


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


def keep_patch(key: str, source: str, patch: ModelPatch) -> None:
    """Keep ``patch`` in the cache as the way to make the entry ``key`` from the entry ``source``.
    Its dampratio rule must be settled (read off the source model by the caller): a kept patch with
    none is refused when read, so that using it never costs a probe of the source model."""
    default_store().save_patch(key, source, patch.to_data())


def kept_model(key: str) -> mujoco.MjModel | None:
    """The model of the entry ``key`` made from a kept patch (see :func:`keep_patch`): its source
    entry, loaded as every entry is (its files checked), and patched; None when either is missing."""
    kept = default_store().load_patch(key)
    if kept is None:
        return None
    source, data = kept
    try:
        patch = ModelPatch.from_data(data)
    except ValueError:
        return None
    model = load_entry(source, counted=False)
    if model is None or not all(isinstance(getattr(model, name, None), np.ndarray) for name in patch.fields):
        return None  # an entry or a field gone (a file edited by hand): a miss, compiled again
    try:
        apply_patch(model, patch)
    except (IndexError, TypeError, ValueError):  # values that do not fit the model: a miss
        return None
    return model
