"""``assembler variants``: one MJCF per variant of a robot (a grid, seeded random draws), in parallel."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Literal

from assembler.assembly import DEFAULT
from assembler.cli.common import gripper_choices, robot_name
from assembler.documents import SPEC_SUFFIXES
from assembler.paths import display_path
from assembler.registry import robot_class
from assembler.variants import MANIFEST, Draw, Grid, VariantPlan, failures, write_variants


def plan_from(args: argparse.Namespace) -> VariantPlan:
    """The variant plan the flags describe; flag mistakes are errors naming the flag (the plan's rules)."""
    name = robot_name(args.robot)
    laws: tuple[Literal["uniform", "normal"], ...] = ("uniform", "normal")
    draws = tuple(Draw.parse(text, law) for law in laws for text in getattr(args, law))
    grids = tuple(Grid.parse(text) for text in args.grid)
    grippers = gripper_choices(args.gripper)
    if args.no_grippers:
        grippers = {arm: None for arm in getattr(robot_class(name).spec, "arms", ())}
    robot_file = [str(Path(args.robot).resolve())] if args.robot.endswith(SPEC_SUFFIXES) else []
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
    )


def run(args: argparse.Namespace) -> int:
    plan = plan_from(args)
    results = write_variants(plan, args.output, args.jobs or os.cpu_count())
    written = sum(r.file is not None for r in results)
    manifest = display_path(Path(args.output) / MANIFEST)
    folder = display_path(args.output)
    print(f"wrote {written} of {len(results)} variants of {plan.robot} to {folder} ({manifest})")
    problems = failures(results)
    for problem in problems:
        print(str(problem), file=sys.stderr)
    return 1 if problems else 0
