"""``assembler variants``: one MJCF per variant of a robot (a grid, seeded random draws), in parallel."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Literal

from assembler.cli.common import gripper_choices, robot_name
from assembler.files.paths import display_path
from assembler.registry.lookup import robot_class
from assembler.spec.part_arguments import DEFAULT, spec_file_path
from assembler.worlds.variants import MANIFEST, Draw, Grid, VariantPlan, failures, write_variants


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


def run(args: argparse.Namespace) -> int:
    plan = plan_from(args)
    run = write_variants(plan, args.output)
    manifest = display_path(Path(args.output) / MANIFEST)
    folder = display_path(args.output)
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
