"""``assembler inspect``: every joint parameter and actuator of a robot and where each value came from."""

from __future__ import annotations

import argparse
import json

from assembler.cli.common import bare_robot, override_flags, table
from assembler.files.paths import display_path
from assembler.models.actuator_table import ActuatorRecord
from assembler.models.motor_joints import derivation_lines
from assembler.models.physical import PhysicalTable
from assembler.spec.schema import JOINT_RULE_ATTRIBUTES


def run(args: argparse.Namespace) -> int:
    changes = override_flags(args)
    robot = bare_robot(args.robot, args.idn, changes)
    derivations = derivation_lines(robot.naming_prefix, robot.joint_values, robot.actuator_table)
    if args.format == "json":
        joints = {
            robot.naming_prefix + joint: {
                a: {"value": v.value, "source": str(v.source), "origin": v.source.origin}
                for a, v in values.items()
            }
            for joint, values in robot.joint_values.items()
        }
        actuators = {
            robot.naming_prefix + record.name: {
                "joint": robot.naming_prefix + record.joint if record.joint is not None else None,
                "type": record.type,
                "source": record.source,
                "values": {k: {"value": v, "source": s} for k, (v, s) in record.values.items()},
            }
            for record in robot.actuator_table
        }
        physical = robot.physical
        bodies = {
            robot.naming_prefix + body: {f: {"value": v.value, "source": str(v)} for f, v in values.items()}
            for body, values in physical.bodies.items()
        }
        geoms = {
            robot.naming_prefix + geom: {"friction": {"value": list(v.value), "source": str(v)}}  # type: ignore[arg-type]
            for geom, v in physical.geoms.items()
        }
        summary = {
            "robot": type(robot).__name__,
            "dof": robot.dof,
            "joints": joints,
            "actuators": actuators,
            "bodies": bodies,
            "geoms": geoms,
            "motor_derivations": derivations,
        }
        print(json.dumps(summary, indent=2))
        return 0
    loaded = type(robot).loaded
    print(f"{type(robot).__name__}: {robot.spec.morphology}, {robot.dof} dof, prefix {robot.naming_prefix}")
    if loaded is not None:
        print(f"spec: {loaded.source}")
    if changes:
        print("overrides: " + ", ".join(f"{c.key}={json.dumps(c.value, default=str)}" for c in changes))
    print(f"{robot.spec.source_field}: {display_path(robot.source.path)}")
    for note in [*robot.source.notes, *robot.conventions_applied()]:
        print(f"note: {note}")
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
    if robot.actuator_table:
        print()
        print(table(_actuator_rows(robot.naming_prefix, robot.actuator_table)))
    if robot.physical.bodies or robot.physical.geoms:
        print()
        print(table(_physical_rows(robot.naming_prefix, robot.physical)))
    if derivations:
        print("\nfrom the motors (value = numbers, then the motor, its motors: entry and the formula):")
        print("\n".join(f"  {line}" for line in derivations))
    return 0


def _physical_rows(prefix: str, physical: PhysicalTable) -> list[list[str]]:
    """One row per scaled body (its factors) and per geom given a friction, with the entry that set each."""
    rows = [["body or geom", "mass factor", "size factor", "inertia factor", "friction", "source"]]
    for body, values in physical.bodies.items():
        size, mass, inertia = physical.factors(body)
        sources = ", ".join(sorted({str(v) for v in values.values()}))
        rows.append([prefix + body, f"{mass:.6g}", f"{size:.6g}", f"{inertia:.6g}", "-", sources])
    for geom, value in physical.geoms.items():
        friction = " ".join(f"{v:g}" for v in value.value)  # type: ignore[union-attr]
        rows.append([prefix + geom, "-", "-", "-", friction, str(value)])
    return rows


def _actuator_rows(prefix: str, records: list[ActuatorRecord]) -> list[list[str]]:
    """One row per actuator: its joint, type and source, then each value with where it came from."""
    rows = [["actuator", "joint", "type", "source", "values"]]
    for record in records:
        values = "; ".join(f"{name} {value} ({source})" for name, (value, source) in record.values.items())
        joint = prefix + record.joint if record.joint is not None else "-"
        rows.append([prefix + record.name, joint, record.type, record.source, values or "-"])
    return rows
