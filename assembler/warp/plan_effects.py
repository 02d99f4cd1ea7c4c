"""What each field a variant plan varies does to the compiled model: probed once, then applied to
every world in arrays.

The CPU patch (:mod:`assembler.patch.patchable`) says which model entries a spec field writes and
how. Instead of resolving and patching every world, each varied field is probed: the reference
world (variant 0) with that one field set to the lowest, middle and highest of the values the
worlds take (a grid: each of its values), each probe a full spec validation and patch. An entry a
drawn field changes is either *set* by it, an affine function of the value (a damping, a gain,
a friction, ``biasprm[1] = -kp``), or *scaled* by it, a power of the value (``body_mass`` by a
``mass_scale``, or by ``size_scale^3``; ``body_inertia`` by ``size_scale^5``); scaled entries
compose by multiplication (a body's mass_scale and size_scale), a set entry has one field writing
it. A grid writes a table: one row per grid value. A plan whose fields fit none of these (two
fields setting one entry, a grid and a draw on one entry) has no :class:`PlanEffects`, and
``put_variants`` patches its worlds one by one instead.

The probes are the plan's validation too: a numeric spec field's bounds are an interval, so when
the lowest and highest values validate, every value between them does; two drawn entries of one
list (a range's low and high, which a rule may compare) are not taken apart this way.
"""

from __future__ import annotations

import functools
import json
from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.models import RobotModel
from assembler.patch.derived import ModelPatch, dampratio_rule
from assembler.patch.patchable import NotPatchable, model_patch
from assembler.patch.resolved import Resolved, resolve_variant
from assembler.spec.documents import Override, parse_overrides, parse_path
from assembler.worlds.variants.plan import VariantPlan

COUPLED_ARM = """\
<mujoco>
  <worldbody>
    <body>
      <joint name="hinge" axis="0 1 0"/>
      <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03"/>
      <body pos="0.3 0 0">
        <joint axis="0 1 0"/>
        <geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03"/>
      </body>
    </body>
  </worldbody>
  <actuator><position joint="hinge" kp="100" dampratio="1"/></actuator>
</mujoco>
"""
"""Two hinges about one axis in a chain (their inertia coupled, where MuJoCo's two dampratio rules
differ), with a dampratio: what this MuJoCo's compiler does with one, read off it once."""

RELATIVE = 1e-9
"""How closely a third probe must follow the law two probes give (relative, floating-point noise)."""


class NoEffects(Exception):
    """A plan whose fields this module cannot turn into arrays: its worlds are patched one by one."""


@dataclass
class FieldEffects:
    """How one model field's entries (flattened) follow the plan's varied fields."""

    base: NDArray[np.float64]
    """The reference world's values (before derived constants), flattened."""
    shape: tuple[int, ...]
    sets: list[tuple[str, NDArray[np.intp], NDArray[np.float64], NDArray[np.float64]]] = field(
        default_factory=list
    )
    """(drawn field, entries, a, b): those entries are ``a * value + b``."""
    tables: list[tuple[str, NDArray[np.intp], NDArray[np.float64]]] = field(default_factory=list)
    """(grid field, entries, rows): those entries are ``rows[position]`` for the grid's position."""
    scales: list[tuple[str, NDArray[np.intp], NDArray[np.float64], float]] = field(default_factory=list)
    """(drawn field, entries, powers, reference value): those entries times ``(value / reference)^power``."""


@dataclass
class PlanEffects:
    """Every field a plan writes, as laws of its varied fields' values (see the module)."""

    fields: dict[str, FieldEffects]
    dampratio: dict[int, float]
    """Actuator -> damping ratio: its ``biasprm[2]`` follows the inertia each world has at qpos0."""
    rule: str
    """How this MuJoCo resolves a dampratio (:func:`assembler.patch.derived.dampratio_rule`)."""
    validated: dict[str, tuple[float, float]]
    """Drawn field -> the range whose values are known valid (its probes' lowest and highest)."""
    check: Callable[[str, float], None]
    """Validate one value of one drawn field (the reference world with it: a spec error names it)."""

    def validate(self, drawn: Mapping[str, NDArray[np.float64]]) -> None:
        """Validate the drawn values outside :attr:`validated` (a normal draw's tails), widening it."""
        for key, values in drawn.items():
            low, high = self.validated[key]
            for value in (float(values.min()), float(values.max())) if values.size else ():
                if not low <= value <= high:
                    self.check(key, value)
                    low, high = min(low, value), max(high, value)
            self.validated[key] = (low, high)

    def arrays(
        self, positions: Mapping[str, NDArray[np.int64]], drawn: Mapping[str, NDArray[np.float64]], n: int
    ) -> dict[str, NDArray[np.float64]]:
        """Each field's values for ``n`` worlds (``positions`` and ``drawn``: :meth:`VariantPlan.columns`),
        shaped ``(n, *field shape)``."""
        out: dict[str, NDArray[np.float64]] = {}
        for name, effects in self.fields.items():
            values = np.repeat(effects.base[None], n, axis=0)
            for key, entries, a, b in effects.sets:
                values[:, entries] = drawn[key][:, None] * a + b
            for key, entries, rows in effects.tables:
                values[:, entries] = rows[positions[key]]
            for key, entries, powers, reference in effects.scales:
                values[:, entries] *= (drawn[key][:, None] / reference) ** powers
            out[name] = values.reshape(n, *effects.shape)
        return out


@functools.cache
def compiler_dampratio_rule() -> str:
    """How this MuJoCo's compiler turns a dampratio into ``biasprm[2]`` (``"diagonal"``: MuJoCo 3's
    ``dof_M0``; ``"inverse"``: 4's ``1 / (M^-1)_ii``), read off :data:`COUPLED_ARM` compiled once: a
    robot whose joints are not coupled at qpos0 cannot tell the two apart."""
    return dampratio_rule(mujoco.MjModel.from_xml_string(COUPLED_ARM), {0: 1.0})


def _written(model: mujoco.MjModel, patch: ModelPatch) -> dict[str, NDArray[np.float64]]:
    """The fields ``patch`` writes, as ``model`` would hold them patched (derived constants aside)."""
    out: dict[str, NDArray[np.float64]] = {}
    for name, row, value in patch.entries:
        if name not in out:
            out[name] = np.array(getattr(model, name), dtype=float)
        out[name][row] = value
    return out


@dataclass
class _Probe:
    """One varied field's probes: its values and, per written field, the flattened values they give."""

    key: str
    values: list[object]
    written: list[dict[str, NDArray[np.float64]]]


def _probe_values(plan: VariantPlan, key: str, drawn: Mapping[str, NDArray[np.float64]]) -> list[object]:
    """A grid's values; a uniform draw's range (its bounds and middle: every value it can draw is
    then validated); a normal draw's lowest, middle and highest value among the worlds."""
    grid = next((g for g in plan.grids if g.key == key), None)
    if grid is not None:
        return list(grid.values)
    draw = next(d for d in plan.draws if d.key == key)
    low, high = (
        (draw.a, draw.b) if draw.law == "uniform" else (float(drawn[key].min()), float(drawn[key].max()))
    )
    return [low, high] if low == high else [low, (low + high) / 2, high]


def _law_of_one(
    values: NDArray[np.float64], ys: NDArray[np.float64]
) -> tuple[NDArray[np.float64], NDArray[np.float64]] | None:
    """(a, b) with ``ys = a * values + b`` for every probe (columns: entries), or None."""
    a = (ys[-1] - ys[0]) / (values[-1] - values[0])
    b = ys[0] - a * values[0]
    fitted = a * values[:, None] + b
    return (a, b) if np.allclose(fitted, ys, rtol=RELATIVE, atol=RELATIVE * np.abs(ys).max()) else None


def _powers(values: NDArray[np.float64], ys: NDArray[np.float64]) -> NDArray[np.float64] | None:
    """Powers p with ``ys = ys[0] * (values / values[0])^p`` for every probe, or None."""
    if (values <= 0).any() or (ys[0] == 0).any() or (np.sign(ys) != np.sign(ys[0])).any():
        return None
    powers = np.log(ys[-1] / ys[0]) / np.log(values[-1] / values[0])
    fitted = ys[0] * (values[:, None] / values[0]) ** powers
    return powers if np.allclose(fitted, ys, rtol=RELATIVE, atol=0) else None


def plan_effects(
    plan: VariantPlan,
    robot: RobotModel,
    model: mujoco.MjModel,
    positions: Mapping[str, NDArray[np.int64]],
    drawn: Mapping[str, NDArray[np.float64]],
) -> PlanEffects:
    """The laws of every field the plan writes, from a few probes of each varied field (see the
    module); a :class:`NotPatchable` names the world and field a compile would need, a spec error the
    value refused; :class:`NoEffects` when the plan's fields do not fit the laws."""
    keys = plan.varied()
    parents = [parse_path(key)[:-1] for key in keys if isinstance(parse_path(key)[-1], int)]
    if len(parents) != len(set(parents)):
        raise NoEffects("two drawn entries of one list are validated together, world by world")
    fixed = parse_overrides(plan.fixed, "--set ")
    paths = {key: parse_path(key) for key in keys}
    flags = {key: plan.flag_of(key) + " " for key in keys}
    reference = plan.variant(0)
    own = Resolved.of(robot)

    def patch_of(values: Mapping[str, object], label: str) -> ModelPatch:
        items = [*fixed, *(Override(paths[k], v, flags[k]) for k, v in values.items())]
        try:
            return model_patch(model, own, resolve_variant(robot, own, items))
        except NotPatchable as error:
            raise NotPatchable(f"{label}: {error}") from None

    texts = ", ".join(f"{key}={json.dumps(value)}" for key, value in reference.items())
    ref_patch = patch_of(reference, f"world 0 ({texts})")
    ref_written = _written(model, ref_patch)
    probes = []
    for key in keys:
        values = _probe_values(plan, key, drawn)
        written = []
        for value in values:
            label = f"world {_world_of(plan, key, value, positions, drawn)} ({key}={json.dumps(value)})"
            written.append(_written(model, patch_of(reference | {key: value}, label)))
        probes.append(_Probe(key, values, written))
    names = sorted({*ref_written, *(n for p in probes for w in p.written for n in w)})
    fields = {}
    for name in names:
        base = ref_written.get(name, np.asarray(getattr(model, name), dtype=float))
        fields[name] = _field_effects(plan, name, base, probes, model, reference)
    ranges = {p.key: np.asarray(p.values, dtype=float) for p in probes if p.key not in positions}
    validated = {key: (float(values.min()), float(values.max())) for key, values in ranges.items()}

    def check(key: str, value: float) -> None:
        patch_of(reference | {key: value}, f"{key}={json.dumps(value)}")

    rule = compiler_dampratio_rule()
    return PlanEffects(fields, dict(ref_patch.dampratio), rule, validated, check)


def _world_of(
    plan: VariantPlan,
    key: str,
    value: object,
    positions: Mapping[str, NDArray[np.int64]],
    drawn: Mapping[str, NDArray[np.float64]],
) -> str:
    """A world taking ``value`` of ``key`` (its index), or the worlds it lies between."""
    if key in positions:
        grid = next(g for g in plan.grids if g.key == key)
        return str(int(np.argmax(positions[key] == grid.values.index(value))))
    hits = np.flatnonzero(drawn[key] == value)
    if hits.size:
        return str(int(hits[0]))
    return f"between {int(np.argmin(drawn[key]))} and {int(np.argmax(drawn[key]))}"


def _field_effects(
    plan: VariantPlan,
    name: str,
    base: NDArray[np.float64],
    probes: Sequence[_Probe],
    model: mujoco.MjModel,
    reference: Mapping[str, object],
) -> FieldEffects:
    effects = FieldEffects(base.reshape(-1).copy(), base.shape)
    flat = effects.base
    touched: dict[str, NDArray[np.intp]] = {}
    stacks: dict[str, NDArray[np.float64]] = {}
    for probe in probes:
        default = np.asarray(getattr(model, name), dtype=float).reshape(-1)
        ys = np.stack([w[name].reshape(-1) if name in w else default for w in probe.written])
        changed = np.flatnonzero((ys != flat).any(axis=0))
        if changed.size:
            touched[probe.key], stacks[probe.key] = changed, ys[:, changed]
    counts = np.zeros(flat.size, dtype=int)
    for entries in touched.values():
        counts[entries] += 1
    grids = {g.key for g in plan.grids}
    for key, entries in touched.items():
        ys = stacks[key]
        probe = next(p for p in probes if p.key == key)
        alone = counts[entries] == 1
        if key in grids:
            if not alone.all():
                raise NoEffects(f"{name}: a grid ({key}) and another field write the same entries")
            effects.tables.append((key, entries, ys))
            continue
        values = np.asarray(probe.values, dtype=float)
        law = _law_of_one(values, ys) if alone.all() else None
        if law is not None:
            effects.sets.append((key, entries, *law))
            continue
        powers = _powers(values, ys)
        if powers is None:
            raise NoEffects(f"{name}: {key} writes entries by a law other than a line or a power")
        ref_value = float(reference[key])  # type: ignore[arg-type]
        scale = (ref_value / values[0]) ** powers  # the probes' first value -> the reference's
        effects.scales.append((key, entries, powers, ref_value))
        if not np.allclose(ys[0] * scale, flat[entries], rtol=RELATIVE, atol=0):
            raise NoEffects(f"{name}: {key} scales entries other fields also set")
    return effects
