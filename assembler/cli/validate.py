"""``assembler validate``: check spec files and folders (schema, names, optionally a compile)."""

from __future__ import annotations

import argparse
import sys

from assembler.cli.report import print_problems
from assembler.errors import AssemblerError
from assembler.validation import validate_specs


def run(args: argparse.Namespace) -> int:
    try:
        paths = args.paths or args.specs
        if not paths:
            raise AssemblerError("validate: give spec files or folders (or --specs DIR)")
        report = validate_specs(paths, compile=args.compile)
    except AssemblerError as error:  # printed in the chosen format (GitHub annotations in CI)
        print_problems(error.problems, args.format)
        return 1
    for missing in report.missing.values():
        count = len(missing.specs)
        print(f"note: {count} spec(s) checked without their model file ({missing.message})", file=sys.stderr)
    what = "validated and compiled" if args.compile else "valid"
    print(f"{len(report.classes)} spec(s) {what}: {', '.join(c.__name__ for c in report.classes)}")
    return 0
