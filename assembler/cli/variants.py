"""``assembler variants``: one MJCF per variant of a robot (a grid, seeded random draws), in parallel."""

from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path
from typing import Literal

from assembler.assembly import DEFAULT
from assembler.cache.settings import DISABLE_VARIABLE
from assembler.cli.common import add_assembly_arguments, gripper_choices, robot_name
from assembler.errors import AssemblerError
from assembler.loader import SPEC_SUFFIXES
from assembler.paths import display_path
from assembler.registry import robot_class
from assembler.variants import MANIFEST, Draw, Grid, VariantPlan, VariantResult, failures, write_variants


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("variants", help="one MJCF per variant: a grid of values, random draws")
    add_assembly_arguments(parser)
    parser.add_argument("-o", "--output", required=True, metavar="DIR", help="folder for the variants")
    parser.add_argument(
        "--grid", action="append", default=[], metavar="PATH=V1,V2", help="values of a field (repeatable)"
    )
    parser.add_argument("--random", type=int, metavar="N", help="N random variants (per grid point)")
    parser.add_argument("--seed", type=int, default=0, help="seed of the random draws (default 0)")
    parser.add_argument(
        "--uniform", action="append", default=[], metavar="PATH=LOW:HIGH", help="uniform draw (repeatable)"
    )
    parser.add_argument(
        "--normal", action="append", default=[], metavar="PATH=MEAN:STD", help="normal draw (repeatable)"
    )
    parser.add_argument("--jobs", type=int, help="worker processes (default: all cores)")
    parser.set_defaults(run=run)


def plan_from(args: argparse.Namespace) -> VariantPlan:
    """The variant plan the flags describe; flag mistakes are errors naming the flag."""
    name = robot_name(args.robot)
    laws: tuple[tuple[str, Literal["uniform", "normal"]], ...] = (
        ("uniform", "uniform"),
        ("normal", "normal"),
    )
    draws = tuple(Draw.parse(text, law) for flag, law in laws for text in getattr(args, flag))
    grids = tuple(Grid.parse(text) for text in args.grid)
    keys = [g.key for g in grids] + [d.key for d in draws]
    twice = sorted({key for key in keys if keys.count(key) > 1})
    if twice:
        raise AssemblerError(f"{', '.join(twice)}: varied by two flags; vary each field once")
    if draws and args.random is None:
        raise AssemblerError("--uniform/--normal draw values for --random N variants; add --random N")
    if args.random is not None and (args.random < 1 or not draws):
        raise AssemblerError("--random N needs N >= 1 and at least one --uniform or --normal range")
    if args.seed < 0 or (args.jobs is not None and args.jobs < 1):
        raise AssemblerError("--seed must be >= 0 and --jobs >= 1")
    if not grids and not draws:
        raise AssemblerError("nothing to vary: give --grid PATH=V1,V2,... or --random N with ranges")
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
        count=args.random or 1,
        seed=args.seed,
        spec_paths=(*(str(Path(p).resolve()) for p in args.specs), *robot_file),
    )


def _write(plan: VariantPlan, args: argparse.Namespace) -> list[VariantResult]:
    """Write the variants; ``--no-cache`` reaches the worker processes through their environment."""
    before = os.environ.get(DISABLE_VARIABLE)
    if getattr(args, "no_cache", False):
        os.environ[DISABLE_VARIABLE] = "1"
    try:
        return write_variants(plan, args.output, args.jobs or os.cpu_count())
    finally:
        if before is None:
            os.environ.pop(DISABLE_VARIABLE, None)
        else:
            os.environ[DISABLE_VARIABLE] = before


def run(args: argparse.Namespace) -> int:
    plan = plan_from(args)
    results = _write(plan, args)
    written = sum(r.file is not None for r in results)
    manifest = display_path(Path(args.output) / MANIFEST)
    folder = display_path(args.output)
    print(f"wrote {written} of {len(results)} variants of {plan.robot} to {folder} ({manifest})")
    problems = failures(results)
    for problem in problems:
        print(str(problem), file=sys.stderr)
    return 1 if problems else 0
