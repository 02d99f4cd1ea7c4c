"""``assembler new MODEL_FILE``: write a first spec for a vendor's MJCF or URDF (every guess commented)."""

from __future__ import annotations

import argparse
from pathlib import Path

from assembler.files.paths import display_path
from assembler.tools.new import write_new_spec


def run(args: argparse.Namespace) -> int:
    output = Path(args.output) if args.output else None
    written, target = write_new_spec(Path(args.model_file), output, args.kind, args.force)
    print(
        f"wrote {display_path(target)}: {written.kind} {written.name}; check each 'guess:' and settle each "
        f"'decide:' comment, then: assembler validate {display_path(target)} --compile"
    )
    return 0
