"""The ``assembler`` command: parse arguments, call the API, print, return an exit code.

Arguments are defined in :mod:`assembler.cli.arguments` (light: ``--help`` imports nothing else);
each subcommand's ``run_<command>(args)`` lives in the module of its kind
(:mod:`~assembler.cli.build`, :mod:`~assembler.cli.checking`, :mod:`~assembler.cli.showing`,
:mod:`~assembler.cli.making`), imported when it runs (:func:`assembler.cli.common.run_command`).
Exit codes: 0 success, 1 a problem in the user's input (one line per problem, no traceback), 2 a
usage error (argparse's own), 130 interrupted, 141 output closed early (:mod:`assembler.cli.endings`).
"""

from __future__ import annotations

import importlib
import os
import signal
import sys
import threading
from collections.abc import Sequence
from types import FrameType


def _interrupted_while_starting(signum: int, frame: FrameType | None) -> None:
    """Ctrl-C while the command's own modules are imported: nothing has started, nothing is to undo;
    the line and exit code of :mod:`assembler.cli.endings` (130), not a traceback and a death by SIGINT."""
    os.write(2, b"interrupted\n")
    os._exit(130)


# Until main() runs its command inside end_cleanly, a KeyboardInterrupt would escape the console
# script as a traceback and a death by SIGINT (-2). Only while this module imports, and only in a
# process whose Ctrl-C is Python's own: a program importing the CLI keeps its handler afterwards.
_STARTING = (
    threading.current_thread() is threading.main_thread()
    and signal.getsignal(signal.SIGINT) is signal.default_int_handler
)
if _STARTING:
    signal.signal(signal.SIGINT, _interrupted_while_starting)

from assembler.cli.arguments import build_parser, parse  # noqa: E402 - after the handler, on purpose
from assembler.cli.endings import end_cleanly  # noqa: E402
from assembler.errors import AssemblerError  # noqa: E402
from assembler.files.cache_location import switched_off  # noqa: E402

if _STARTING:  # an import that failed otherwise ends the process with its traceback anyway
    signal.signal(signal.SIGINT, signal.default_int_handler)

__all__ = ["build_parser", "main", "parse", "run"]


def working_folder() -> str:
    """The working folder; :class:`AssemblerError` when it no longer exists."""
    try:
        return os.getcwd()
    except OSError as error:
        raise AssemblerError(
            f"the working folder cannot be read ({error.strerror}): it was deleted or moved away; "
            "cd to a folder that exists and run the command again"
        ) from None


def run() -> int:
    """The ``assembler`` console script: :func:`main` on the process's arguments, in a process that
    exits when it returns (a late Ctrl-C changes nothing, see :func:`~assembler.cli.endings.end_cleanly`)."""
    return main(sys.argv[1:], process_ends=True)


def main(argv: Sequence[str] | None = None, *, process_ends: bool = False) -> int:
    """The ``assembler`` command; returns its exit code. ``process_ends``: called as the process's
    entry point, which exits when this returns."""

    def command() -> int:
        args = parse(argv)
        working_folder()  # gone (deleted under the shell): one line, not a traceback from deep inside
        with switched_off(bool(getattr(args, "no_cache", False))):
            if args.command == "build":  # a build made before is answered before any spec is read
                answered = importlib.import_module("assembler.cli.cached_build").answer(args)
                if answered is not None:
                    return int(answered)
            common = importlib.import_module("assembler.cli.common")  # the heavy part, after parsing
            return int(common.run_command(args))

    return end_cleanly(command, process_ends=process_ends)
