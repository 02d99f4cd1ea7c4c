"""The ``assembler`` command: parse arguments, call the API, print, return an exit code.

Arguments are defined in :mod:`assembler.cli.arguments` (light: ``--help`` imports nothing else);
each subcommand's ``run(args)`` lives in its own module, imported when it runs
(:mod:`assembler.cli.dispatch`). Exit codes: 0 success, 1 a problem in the user's input (one
line per problem, no traceback), 2 a usage error (argparse's own), 130 interrupted, 141 output
closed early (:mod:`assembler.cli.endings`).
"""

from __future__ import annotations

import importlib
from collections.abc import Sequence

from assembler.cli.arguments import build_parser, parse
from assembler.cli.endings import end_cleanly
from assembler.files.cache_location import switched_off

__all__ = ["build_parser", "main", "parse"]


def main(argv: Sequence[str] | None = None) -> int:
    """The ``assembler`` command; returns its exit code."""

    def command() -> int:
        args = parse(argv)
        with switched_off(bool(getattr(args, "no_cache", False))):
            if args.command == "build":  # a build made before is answered before any spec is read
                answered = importlib.import_module("assembler.cli.cached_build").answer(args)
                if answered is not None:
                    return int(answered)
            dispatch = importlib.import_module("assembler.cli.dispatch")  # the heavy part, after parsing
            return int(dispatch.run_command(args))

    return end_cleanly(command)
