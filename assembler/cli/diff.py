"""``assembler diff A B``: what changed between two specs, in the spec and in the compiled model; or
between two lock files (``robot-assembler.lock@HEAD robot-assembler.lock``), robot by robot."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.tools.diff import FORMATS, compare
from assembler.tools.diff.revision import text_at
from assembler.tools.lock import Lock, lock_changes, parse_lock, read_lock


def _lock(reference: str) -> Lock:
    """A lock file, or ``FILE@REV`` for its text at a git revision."""
    path, _, revision = reference.rpartition("@") if "@" in reference else (reference, "", "")
    if revision:
        return parse_lock(text_at(Path(path), revision), reference)
    return read_lock(Path(reference))


def run(args: argparse.Namespace) -> int:
    if all(reference.partition("@")[0].endswith(".lock") for reference in (args.before, args.after)):
        lines = lock_changes(_lock(args.before), _lock(args.after))  # a lock change, robot by robot
        sys.stdout.write("".join(line + "\n" for line in lines) or "the locks are the same\n")
        return 1 if args.exit_code and lines else 0
    comparison = compare(args.before, args.after)
    sys.stdout.write(FORMATS[args.format](comparison))
    return 1 if args.exit_code and not comparison.identical else 0
