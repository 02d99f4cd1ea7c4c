"""Which varied fields changed nothing in the compiled model, so a sweep says so instead of writing
N byte-identical "variants" (``joint_defaults.damping`` on a robot whose ``joints:`` set damping on
every joint, say).

A field has an effect when two variants that differ in it alone came out different. Grids give
such pairs directly; where none was built (random draws vary every field at once) one probe is
built: the first variant with only this field changed to another variant's value.
"""

from __future__ import annotations

import hashlib
from collections.abc import Sequence
from typing import Any

from assembler.errors import AssemblerError
from assembler.worlds.variants.plan import VariantPlan
from assembler.worlds.variants.run import VariantResult, variant_xml


def _differs_only_in(a: dict[str, Any], b: dict[str, Any], key: str) -> bool:
    return a[key] != b[key] and all(a[other] == b[other] for other in a if other != key)


def _has_effect(
    plan: VariantPlan, written: Sequence[VariantResult], variants: list[dict[str, Any]], key: str
) -> bool:
    digests = {result.index: result.sha256 for result in written}
    pairs = [
        (i, j) for i in digests for j in digests if i < j and _differs_only_in(variants[i], variants[j], key)
    ]
    if pairs:
        return any(digests[i] != digests[j] for i, j in pairs)
    first = min(digests)
    other = next((v for v in variants if v[key] != variants[first][key]), None)
    if other is None:
        return False  # every value the same: nothing was varied
    probe = {**variants[first], key: other[key]}
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
    variants = plan.variant_overrides()
    return [key for key in plan.varied() if not _has_effect(plan, written, variants, key)]
