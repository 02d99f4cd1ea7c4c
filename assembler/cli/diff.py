"""``assembler diff A B``: what changed between two specs, in the spec and in the compiled model."""

from __future__ import annotations

import argparse
import sys

from assembler.diff import FORMATS, compare


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser(
        "diff",
        help="compare two specs: changed fields and compiled-model differences",
        description="Compare two specs: the fields that changed, and what changed in the compiled "
        "model (robots with their default base and grippers). Each side is a spec file, a registered "
        "name, or FILE@REVISION (read with git show; a parent spec it extends by file path is read "
        "at the same revision, its MJCF from the working tree).",
    )
    parser.add_argument("before", help="spec file, registered name or FILE@REV (e.g. specs/x.yaml@HEAD~1)")
    parser.add_argument("after", help="spec file, registered name or FILE@REV")
    parser.add_argument(
        "--format", choices=sorted(FORMATS), default="text", help="output format (default: text)"
    )
    parser.add_argument(
        "--exit-code", action="store_true", help="exit with 1 when they differ, 0 when not (like git diff)"
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    comparison = compare(args.before, args.after)
    sys.stdout.write(FORMATS[args.format](comparison))
    return 1 if args.exit_code and not comparison.identical else 0
