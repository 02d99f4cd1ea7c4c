"""Variants of one robot: a grid of override values and seeded random draws, built in parallel
(:mod:`~assembler.worlds.variants.plan`, :mod:`~assembler.worlds.variants.run`), and which varied
fields changed nothing (:mod:`~assembler.worlds.variants.effects`, the rule ``build --set`` follows too)."""

from pathlib import Path

from assembler.worlds.variants.effects import fields_without_effect
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan
from assembler.worlds.variants.run import (
    Progress,
    VariantResult,
    VariantRun,
    failures,
    run_variants,
    write_manifest,
)
from assembler.worlds.variants.shards import MANIFEST, Shard, merge_shards

__all__ = [
    "MANIFEST",
    "Draw",
    "Progress",
    "Grid",
    "VariantPlan",
    "VariantResult",
    "VariantRun",
    "Shard",
    "failures",
    "merge_shards",
    "run_variants",
    "write_manifest",
    "write_variants",
]


def write_variants(
    plan: VariantPlan, folder: str | Path, shard: Shard | None = None, progress: Progress | None = None
) -> VariantRun:
    """Build every variant of ``plan`` (or of one ``shard``) into ``folder`` (see :func:`run_variants`),
    and find the varied fields that changed nothing in what was written."""
    results = run_variants(plan, folder, shard, progress)
    return VariantRun(results, fields_without_effect(plan, results, folder))
