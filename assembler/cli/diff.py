"""``assembler diff A B``: what changed between two specs, in the spec and in the compiled model."""

from __future__ import annotations

import argparse
import sys

from assembler.tools.diff import FORMATS, compare


def run(args: argparse.Namespace) -> int:
    comparison = compare(args.before, args.after)
    sys.stdout.write(FORMATS[args.format](comparison))
    return 1 if args.exit_code and not comparison.identical else 0
