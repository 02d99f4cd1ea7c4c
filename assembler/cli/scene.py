"""``assembler scene``: several placed robots from a scene YAML, in one MJCF."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.files.paths import display_path
from assembler.files.writing import write_atomically
from assembler.mjcf.emit import to_xml
from assembler.worlds.scene import load_scene


def run(args: argparse.Namespace) -> int:
    scene = load_scene(args.scene)
    scene.get_model()  # compile first: a scene that does not compile writes nothing
    xml = to_xml(scene.mjspec)
    if args.output:
        write_atomically(Path(args.output), xml)
        names = ", ".join(robot.name for robot in scene.robots)
        print(f"wrote {display_path(args.output)} ({names})", file=sys.stderr)
    else:
        sys.stdout.write(xml)
    return 0
