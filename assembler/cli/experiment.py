"""``assembler experiment``: an experiment file's robots (with their overrides) in one MJCF.

A command of its own rather than a mode of ``scene``: an experiment with one robot is that robot's
standalone model (what ``build --set ...`` writes, no floor added), and the summary line says
which overrides each robot got, which is what a reviewer of an experiment wants to see.
"""

from __future__ import annotations

import argparse
import json
import sys
from pathlib import Path

from assembler.files.paths import display_path
from assembler.files.writing import write_atomically
from assembler.models import RobotModel
from assembler.registry.catalog import applied_overrides
from assembler.worlds.experiment import load_experiment


def describe(robot: RobotModel) -> str:
    """``Sparrow70 (joint_defaults.damping=0.2)``: a robot and the overrides it was built with."""
    changes = applied_overrides(type(robot))
    if not changes:
        return robot.name
    return f"{robot.name} ({', '.join(f'{c.key}={json.dumps(c.value, default=str)}' for c in changes)})"


def run(args: argparse.Namespace) -> int:
    experiment = load_experiment(args.experiment)
    xml = experiment.get_xml()  # compiled first: an experiment that does not compile writes nothing
    if args.output:
        write_atomically(Path(args.output), xml)
        names = ", ".join(describe(robot) for robot in experiment.robots)
        print(f"wrote {display_path(args.output)}: {names}", file=sys.stderr)
    else:
        sys.stdout.write(xml)
    return 0
