"""Which varied fields changed nothing in the compiled model, so a sweep says so instead of writing
N byte-identical "variants" (``joint_defaults.damping`` on a robot whose ``joints:`` set damping on
every joint, say).

A field has an effect when two variants that differ in it alone came out different. Grids give
such pairs directly; where none was built (random draws vary every field at once) one probe is
built: the first variant with only this field changed to another variant's value.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Sequence
from typing import Any

from assembler.errors import AssemblerError
from assembler.worlds.variants.plan import VariantPlan
from assembler.worlds.variants.run import VariantResult, variant_xml


def _shown(value: Any) -> str:
    """A value as a hashable, comparable key (grid values may be lists or mappings)."""
    return json.dumps(value, sort_keys=True, default=str)


def _has_effect(plan: VariantPlan, written: Sequence[VariantResult], key: str) -> bool:
    """Whether ``key`` changed a written file: two written variants that differ in it alone differ in
    bytes; where no such pair was written, one probe is built (``key`` set to another variant's value)."""
    values = {result.index: plan.variant(result.index) for result in written}
    digests = {result.index: result.sha256 for result in written}
    alike: dict[str, dict[str, set[str | None]]] = {}  # the other fields -> this field's value -> digests
    for index, variant in values.items():
        others = _shown({other: value for other, value in variant.items() if other != key})
        alike.setdefault(others, {}).setdefault(_shown(variant[key]), set()).add(digests[index])
    groups = [by_value for by_value in alike.values() if len(by_value) > 1]
    if groups:
        return any(len(set().union(*by_value.values())) > 1 for by_value in groups)
    first = min(values)
    other = next((v for v in plan.variants() if v[key] != values[first][key]), None)
    if other is None:
        return False  # every value the same: nothing was varied
    probe = {**values[first], key: other[key]}
    try:
        data = variant_xml(plan, probe).encode()
    except AssemblerError:
        return True  # the value matters enough to break the build
    return hashlib.sha256(data).hexdigest() != digests[first]


def fields_without_effect(plan: VariantPlan, results: Sequence[VariantResult]) -> list[str]:
    """The varied fields that made no difference to the written models, in the plan's order."""
    written = [result for result in results if result.file is not None]
    if not written:
        return []
    return [key for key in plan.varied() if not _has_effect(plan, written, key)]
