"""``assembler inspect``: every joint parameter of a robot and where each value came from."""

from __future__ import annotations

import argparse
import json

from assembler.cli.common import bare_robot, override_flags, table
from assembler.paths import display_path
from assembler.schema import JOINT_RULE_ATTRIBUTES


def run(args: argparse.Namespace) -> int:
    changes = override_flags(args)
    robot = bare_robot(args.robot, args.idn, changes)
    if args.format == "json":
        joints = {
            robot.naming_prefix + joint: {
                a: {"value": v.value, "source": str(v.source), "origin": v.source.origin}
                for a, v in values.items()
            }
            for joint, values in robot.joint_values.items()
        }
        print(json.dumps({"robot": type(robot).__name__, "dof": robot.dof, "joints": joints}, indent=2))
        return 0
    loaded = type(robot).loaded
    print(f"{type(robot).__name__}: {robot.spec.morphology}, {robot.dof} dof, prefix {robot.naming_prefix}")
    if loaded is not None:
        print(f"spec: {loaded.source}")
    if changes:
        print("overrides: " + ", ".join(f"{c.key}={json.dumps(c.value, default=str)}" for c in changes))
    print(f"mjcf: {display_path(robot.source.path)}")
    attributes = list(JOINT_RULE_ATTRIBUTES) + sorted(
        {a for values in robot.joint_values.values() for a in values} - set(JOINT_RULE_ATTRIBUTES)
    )
    rows = [["joint", *attributes]]
    for joint, values in robot.joint_values.items():
        cells = [robot.naming_prefix + joint]
        for attribute in attributes:
            value = values.get(attribute)
            cells.append(f"{value.value:.6g}  {value.source}" if value else "-  (MuJoCo default)")
        rows.append(cells)
    print(table(rows))
    return 0
