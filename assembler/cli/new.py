"""``assembler new MODEL_FILE``: write a first spec for a vendor's MJCF or URDF (every guess commented)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.files.paths import display_path
from assembler.tools.new import write_new_spec
from assembler.tools.new.checking import build_problems


def run(args: argparse.Namespace) -> int:
    output = Path(args.output) if args.output else None
    written, target = write_new_spec(Path(args.model_file), output, args.kind, args.force)
    problems = build_problems(target, written.kind)
    print(f"wrote {display_path(target)}: {written.kind} {written.name}", end="")
    if not problems:
        print(" (validated and compiled); check each 'guess:' and settle each 'decide:' comment")
        return 0
    print("; it does not build as written:")
    for line in problems:
        print(line, file=sys.stderr)
    return 1
