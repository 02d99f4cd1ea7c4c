"""``assembler validate``: check spec files and folders (schema, names, optionally a compile)."""

from __future__ import annotations

import argparse
import sys

from assembler.cli.report import add_format_argument, print_problems
from assembler.errors import AssemblerError
from assembler.validation import validate_specs

FORMATS = ("text", "github")
"""validate prints problems only: as lines, or as GitHub annotations."""


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("validate", help="check spec files and folders")
    parser.add_argument("paths", nargs="+", help="spec files or folders")
    parser.add_argument("--compile", action="store_true", help="also compile each robot with MuJoCo")
    add_format_argument(parser, FORMATS)
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    try:
        report = validate_specs(args.paths, compile=args.compile)
    except AssemblerError as error:  # printed in the chosen format (GitHub annotations in CI)
        print_problems(error.problems, args.format)
        return 1
    if report.unchecked:
        print(
            f"note: {len(report.unchecked)} spec(s) checked without their MJCF ({report.missing})",
            file=sys.stderr,
        )
    what = "validated and compiled" if args.compile else "valid"
    print(f"{len(report.classes)} spec(s) {what}: {', '.join(c.__name__ for c in report.classes)}")
    return 0
