"""``assembler variants``: one MJCF per variant of a robot (a grid, seeded random draws), in parallel."""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path
from typing import Literal

from assembler.cli.common import gripper_choices, robot_name
from assembler.files.paths import display_path
from assembler.registry.lookup import robot_class
from assembler.spec.part_arguments import DEFAULT, spec_file_path
from assembler.worlds.variants import (
    MANIFEST,
    Draw,
    Grid,
    Progress,
    Shard,
    VariantPlan,
    failures,
    merge_shards,
    write_variants,
)


def plan_from(args: argparse.Namespace) -> VariantPlan:
    """The variant plan the flags describe; flag mistakes are errors naming the flag (the plan's rules)."""
    name = robot_name(args.robot)
    laws: tuple[Literal["uniform", "normal"], ...] = ("uniform", "normal")
    draws = tuple(Draw.parse(text, law) for law in laws for text in getattr(args, law))
    grids = tuple(Grid.parse(text) for text in args.grid)
    grippers = gripper_choices(args.gripper)
    if args.no_grippers:
        grippers = {arm: None for arm in getattr(robot_class(name).spec, "arms", ())}
    spec_file = spec_file_path(args.robot)
    robot_file = [str(spec_file)] if spec_file is not None else []
    return VariantPlan(
        robot=name,
        idn=args.idn,
        base=None if args.no_base else (args.base or DEFAULT),
        grippers=tuple(grippers.items()),
        fixed=tuple(args.overrides),
        grids=grids,
        draws=draws,
        random=args.random,
        seed=args.seed,
        spec_paths=(*(str(Path(p).resolve()) for p in args.specs), *robot_file),
        cache=not args.no_cache,
        store=args.cache,
        jobs=args.jobs,
    )


LARGE = 10_000
"""From this many variants a run states its size first and reports progress as it goes."""

PROGRESS_SECONDS = 5.0
"""How often a long run says how far it is."""


def _progress(robot: str) -> Progress:
    """Say every few seconds how many of the run's variants are done (a long run is never silent)."""
    said = time.monotonic()

    def tell(done: int, count: int) -> None:
        nonlocal said
        now = time.monotonic()
        if now - said >= PROGRESS_SECONDS and done < count:
            said = now
            print(f"variants of {robot}: {done:,} of {count:,} done ({done / count:.1%})", file=sys.stderr)

    return tell


def run(args: argparse.Namespace) -> int:
    plan = plan_from(args)
    folder = display_path(args.output)
    if args.merge is not None:
        listed = merge_shards(plan, args.output, args.merge)
        manifest = display_path(Path(args.output) / MANIFEST)
        print(
            f"merged {args.merge} shards of {plan.robot} in {folder}: {manifest} lists {listed}",
            file=sys.stderr,
        )
        return 0
    shard = Shard.parse(args.shard) if args.shard is not None else None
    count = plan.size if shard is None else len(plan.shard(shard.number, shard.shards))
    if plan.size >= LARGE:
        part = "" if shard is None else f"; shard {shard.number}/{shard.shards}: {count:,} of them"
        print(f"a plan of {plan.size:,} variants of {plan.robot}{part}", file=sys.stderr)
    run = write_variants(plan, args.output, shard, _progress(plan.robot))
    manifest = display_path(Path(args.output) / (MANIFEST if shard is None else shard.manifest_name))
    models = f"{run.distinct} distinct model{'s' if run.distinct != 1 else ''}"
    written = f"wrote {len(run.written)} of {len(run.results)} variants of {plan.robot}"
    print(f"{written} to {folder} ({manifest}): {models}", file=sys.stderr)  # as every command's "wrote"
    for key in run.no_effect:
        print(
            f"warning: {plan.flag_of(key)} {key} changes nothing in the compiled model (variants that differ "
            "only in it are byte-identical); see what else in the spec sets it",
            file=sys.stderr,
        )
    problems = failures(run.results)
    for problem in problems:
        print(str(problem), file=sys.stderr)
    return 1 if problems else 0
