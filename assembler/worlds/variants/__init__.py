"""Variants of one robot: a grid of override values and seeded random draws, built in parallel
(:mod:`~assembler.worlds.variants.plan`, :mod:`~assembler.worlds.variants.run`), and which varied
fields changed nothing (:mod:`~assembler.worlds.variants.effects`)."""

from pathlib import Path

from assembler.worlds.variants.effects import fields_without_effect
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan
from assembler.worlds.variants.run import (
    MANIFEST,
    VariantResult,
    VariantRun,
    failures,
    run_variants,
    write_manifest,
)

__all__ = [
    "MANIFEST",
    "Draw",
    "Grid",
    "VariantPlan",
    "VariantResult",
    "VariantRun",
    "failures",
    "fields_without_effect",
    "run_variants",
    "write_manifest",
    "write_variants",
]


def write_variants(plan: VariantPlan, folder: str | Path) -> VariantRun:
    """Build every variant of ``plan`` into ``folder`` (see :func:`run_variants`), and find the varied
    fields that changed nothing."""
    results = run_variants(plan, folder)
    return VariantRun(results, fields_without_effect(plan, results))
