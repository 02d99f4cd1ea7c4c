"""``assembler build``: write a robot's standalone MJCF (to a file, a bundle folder or stdout)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.cli.common import assembled, use_cache, warn_idle_overrides
from assembler.mjcf.emit import bundle_xml
from assembler.paths import display_path


def run(args: argparse.Namespace) -> int:
    robot = assembled(args)
    cache = use_cache(args)
    if args.bundle:
        name = Path(args.output).name if args.output else f"{type(robot).__name__}.xml"
        xml = robot.get_xml(cache=cache)  # compiled first: a robot that does not compile writes nothing
        target = bundle_xml(xml, Path(args.bundle), name)
        print(f"wrote {display_path(target)} with its assets", file=sys.stderr)
    elif args.output:
        target = robot.save(args.output, cache=cache)
        print(f"wrote {display_path(target)}", file=sys.stderr)
    else:
        sys.stdout.write(robot.get_xml(cache=cache))
    warn_idle_overrides(args)
    return 0
