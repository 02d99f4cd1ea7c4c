"""The ``assembler`` command: parse arguments, call the API, print, return an exit code.

Each subcommand lives in its own module with ``add_parser(commands)`` and ``run(args)``.
Exit codes: 0 success, 1 a problem in the user's input (printed one line per problem, no
traceback), 2 a usage error (argparse's own).
"""

from __future__ import annotations

import argparse
import sys
from collections.abc import Sequence

from assembler.catalog import add_spec_folders
from assembler.cli import (
    build,
    cache,
    diff,
    experiment,
    inspect,
    lint,
    listing,
    render,
    scene,
    schema,
    validate,
    variants,
)
from assembler.errors import AssemblerError
from assembler.paths import allowing

COMMANDS = (listing, validate, lint, build, scene, experiment, variants, inspect, schema, diff, render, cache)
"""Subcommand modules, in the order ``assembler --help`` lists them."""


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assembler", description="Assemble MuJoCo robots from declarative YAML specs."
    )
    parser.add_argument(
        "--specs",
        action="append",
        default=[],
        metavar="DIR",
        help="also register the specs in DIR (repeatable)",
    )
    parser.add_argument(
        "--allow-path",
        action="append",
        default=[],
        metavar="DIR",
        help="let specs read files below DIR too (repeatable); by default a spec reads only its own "
        "folder, the shipped specs and assets, and package:// paths (see SECURITY.md)",
    )
    commands = parser.add_subparsers(dest="command", required=True)
    for command in COMMANDS:
        command.add_parser(commands)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        with allowing(args.allow_path):
            add_spec_folders(args.specs)
            return int(args.run(args))
    except AssemblerError as error:
        for problem in error.problems:
            print(str(problem), file=sys.stderr)
        return 1
