"""The ``assembler`` command: parse arguments, call the API, print, return an exit code.

Each subcommand lives in its own module with ``add_parser(commands)`` and ``run(args)``.
Exit codes: 0 success, 1 a problem in the user's input (printed one line per problem, no
traceback), 2 a usage error (argparse's own).
"""

from __future__ import annotations

import argparse
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
from assembler.cli.endings import end_cleanly
from assembler.paths import allowing

COMMANDS = (listing, validate, lint, build, scene, experiment, variants, inspect, schema, diff, render, cache)
"""Subcommand modules, in the order ``assembler --help`` lists them."""


def _add_global_options(parser: argparse.ArgumentParser, after_command: bool) -> None:
    """``--specs`` and ``--allow-path``, before the command or after it (kept apart, then joined)."""
    suffix = "_after" if after_command else ""
    parser.add_argument(
        "--specs",
        action="append",
        default=[],
        dest="specs" + suffix,
        metavar="DIR",
        help="also register the specs in DIR (repeatable)",
    )
    parser.add_argument(
        "--allow-path",
        action="append",
        default=[],
        dest="allow_path" + suffix,
        metavar="DIR",
        help="let specs read files below DIR too (repeatable); by default a spec reads only its own "
        "folder, the shipped specs and assets, and package:// paths (see SECURITY.md)",
    )


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assembler", description="Assemble MuJoCo robots from declarative YAML specs."
    )
    _add_global_options(parser, after_command=False)
    commands = parser.add_subparsers(dest="command", required=True, metavar="COMMAND")
    for command in COMMANDS:
        command.add_parser(commands)
    for subparser in commands.choices.values():
        _add_global_options(subparser, after_command=True)
    return parser


def parse(argv: Sequence[str] | None = None) -> argparse.Namespace:
    """The command line, with the options given before and after the command joined."""
    args = build_parser().parse_args(argv)
    args.specs = [*args.specs, *args.specs_after]
    args.allow_path = [*args.allow_path, *args.allow_path_after]
    return args


def main(argv: Sequence[str] | None = None) -> int:
    """The ``assembler`` command; returns its exit code (see :mod:`assembler.cli.endings`)."""

    def command() -> int:
        args = parse(argv)
        with allowing(args.allow_path):
            add_spec_folders(args.specs)
            return int(args.run(args))

    return end_cleanly(command)
