"""``assembler validate``: check spec files and folders (schema, MJCF names, optionally a compile)."""

from __future__ import annotations

import argparse
import sys

from assembler.assembly import assemble
from assembler.catalog import register_specs
from assembler.cli.report import add_format_argument, print_problems
from assembler.errors import AssemblerError, MissingPackageError, Problem
from assembler.models import RobotModel


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("validate", help="check spec files and folders")
    parser.add_argument("paths", nargs="+", help="spec files or folders")
    parser.add_argument("--compile", action="store_true", help="also compile each robot with MuJoCo")
    add_format_argument(parser, ("text", "github"))
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    try:
        return _validate(args)
    except AssemblerError as error:  # printed in the chosen format (GitHub annotations in CI)
        print_problems(error.problems, args.format)
        return 1


def _validate(args: argparse.Namespace) -> int:
    classes = register_specs(*args.paths)
    problems: list[Problem] = []
    unchecked: list[str] = []
    missing = ""
    for cls in classes:
        try:
            part = cls(idn=0)
            if args.compile:
                if isinstance(part, RobotModel):
                    assemble(cls.__name__, idn=0).get_model()  # with its default base and grippers
                else:
                    part.compile_alone()
        except MissingPackageError as error:
            unchecked.append(cls.__name__)
            missing = error.problems[0].message.split(": ", 1)[-1]
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise AssemblerError(problems)
    if unchecked:
        print(f"note: {len(unchecked)} spec(s) checked without their MJCF ({missing})", file=sys.stderr)
    what = "validated and compiled" if args.compile else "valid"
    print(f"{len(classes)} spec(s) {what}: {', '.join(c.__name__ for c in classes)}")
    return 0
