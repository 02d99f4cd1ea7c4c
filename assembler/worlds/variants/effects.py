"""The one "changed nothing" rule: a ``--set`` override or a varied field has no effect when the
models with and without it are the same (:func:`same_model`), so a build or a sweep can say so.

An override that changes nothing is almost always a mistake a reviewer would want flagged:
``joint_defaults.damping`` on a robot whose ``joints:`` set damping on every joint, say.

- ``build --set`` (:func:`overrides_without_effect`): each override is tested by building without it
  (from the cache when the plain robot is there); an override a later one replaces is idle without
  a build (:func:`superseded`).
- ``variants`` (:func:`fields_without_effect`): a field has an effect when two written variants that
  differ in it alone differ; grids give such pairs directly, and where none was written (random draws
  vary every field at once) one probe is built: the first variant with only this field changed to
  another variant's value. Identical files are the same model without a load (MJCF emission is
  deterministic). Files that differ are different models when the patches that make both variants
  of the plan's robot write values that differ and stay (no model made); else the two models are
  patched in memory where patches describe both (what their texts load to, with no mesh decoded: a
  GR1's text takes ~0.3 s to load) or the texts are loaded, and compared by the same rule.

Models are compared field by field, not byte for byte: one of the two may be a variant patched onto
the cached robot (:mod:`assembler.patch.robot_variant`) and the other compiled, and those agree to
1e-10, not to the last bit.
"""

from __future__ import annotations

import json
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import AssemblerError
from assembler.models import RobotModel
from assembler.spec.documents import Override
from assembler.worlds.variants.plan import VariantPlan
from assembler.worlds.variants.run import VariantResult, variant_model, variant_xml, variants_surely_differ

RELATIVE = 1e-9
"""How close two numbers of two models must be to be the same (a patch agrees with a compile to 1e-10)."""


def _arrays(model: mujoco.MjModel) -> dict[str, NDArray[Any]]:
    return {
        name: value
        for name in dir(model)
        if not name.startswith("_") and isinstance(value := getattr(model, name), np.ndarray)
    }


def same_model(first: mujoco.MjModel, second: mujoco.MjModel) -> bool:
    """True when every array of the two compiled models is the same: integers (counts, addresses,
    names) equal, numbers equal to :data:`RELATIVE` (or 1e-12 absolute)."""
    if mujoco.mj_sizeModel(first) != mujoco.mj_sizeModel(second):
        return False
    mine, theirs = _arrays(first), _arrays(second)
    if mine.keys() != theirs.keys():
        return False
    for name, value in mine.items():
        other = theirs[name]
        if value.shape != other.shape:
            return False
        if np.array_equal(value, other):  # most arrays, meshes first: bit-equal, and cheaper to tell
            continue
        if np.issubdtype(value.dtype, np.floating):
            if not np.allclose(value, other, rtol=RELATIVE, atol=1e-12, equal_nan=True):
                return False
        elif not np.array_equal(value, other):
            return False
    return True


def superseded(overrides: Sequence[Override]) -> list[bool]:
    """For each override, whether a later one sets the same field or a field containing it: its value
    is replaced, so it changes nothing (found in one pass, without building anything)."""
    later: set[tuple[str | int, ...]] = set()
    found = []
    for override in reversed(overrides):
        path = tuple(override.path)
        found.append(any(path[:depth] in later for depth in range(len(path) + 1)))
        later.add(path)
    return found[::-1]


def overrides_without_effect(
    build: Callable[[Sequence[Override]], RobotModel], overrides: Sequence[Override], cache: bool = True
) -> list[Override]:
    """The overrides whose removal leaves the compiled model the same; ``build`` assembles the robot
    with the overrides it is given.

    An override a later one replaces is idle without a build; each other one is removed in turn
    from the overrides that count (one build per field set, not per flag: ``--set`` given 1,280
    times for one field costs two builds, not 1,280 builds of 1,280 overrides each)."""
    if not overrides:
        return []
    replaced = superseded(overrides)
    counting = [index for index, gone in enumerate(replaced) if not gone]
    full = build(overrides).get_model(cache=cache)
    idle = {index for index, gone in enumerate(replaced) if gone}
    for index in counting:
        others = [overrides[other] for other in counting if other != index]
        if same_model(build(others).get_model(cache=cache, store=False), full):
            idle.add(index)
    return [overrides[index] for index in sorted(idle)]


def _shown(value: Any) -> str:
    """A value as a hashable, comparable key (grid values may be lists or mappings)."""
    return json.dumps(value, sort_keys=True, default=str)


def _same_variants(
    plan: VariantPlan, values: tuple[dict[str, Any], dict[str, Any]], texts: tuple[str, str]
) -> bool:
    """Whether two variants (their ``values`` and MJCF ``texts``) are the same model: identical text
    is; other text is compared as models (:func:`same_model`), patched in memory where both can be,
    else loaded."""
    first, second = texts
    if first == second:
        return True
    if variants_surely_differ(plan, *values):
        return False
    patched = [variant_model(plan, variant) for variant in values]
    if patched[0] is not None and patched[1] is not None:
        return same_model(patched[0], patched[1])
    return same_model(mujoco.MjModel.from_xml_string(first), mujoco.MjModel.from_xml_string(second))


def _has_effect(plan: VariantPlan, written: Sequence[VariantResult], folder: Path, key: str) -> bool:
    """Whether ``key`` changed a written variant: two written variants that differ in it alone are
    different models; where no such pair was written, one probe is built."""
    texts: dict[str, str] = {}

    def text(name: str) -> str:
        if name not in texts:
            texts[name] = (folder / name).read_text()
        return texts[name]

    values = {result.index: plan.variant(result.index) for result in written}
    files = {result.index: str(result.file) for result in written}
    alike: dict[str, dict[str, int]] = {}  # the other fields -> this field's value -> a variant with it
    for index, variant in values.items():
        others = _shown({other: value for other, value in variant.items() if other != key})
        alike.setdefault(others, {}).setdefault(_shown(variant[key]), index)
    pairs = [list(by_value.values())[:2] for by_value in alike.values() if len(by_value) > 1]
    if pairs:
        return any(
            not _same_variants(plan, (values[a], values[b]), (text(files[a]), text(files[b])))
            for a, b in pairs
        )
    first = min(values)
    other = next((v for v in plan.variants() if v[key] != values[first][key]), None)
    if other is None:
        return False  # every value the same: nothing was varied
    probe = {**values[first], key: other[key]}
    try:
        probe_text = variant_xml(plan, probe)
    except AssemblerError:
        return True  # the value matters enough to break the build
    return not _same_variants(plan, (probe, values[first]), (probe_text, text(files[first])))


def fields_without_effect(
    plan: VariantPlan, results: Sequence[VariantResult], folder: str | Path
) -> list[str]:
    """The varied fields that made no difference to the variants written in ``folder``, in the
    plan's order."""
    written = [result for result in results if result.file is not None]
    if not written:
        return []
    return [key for key in plan.varied() if not _has_effect(plan, written, Path(folder), key)]
