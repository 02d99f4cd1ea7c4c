"""The commands that show what is there and write no file: ``assembler list`` (the registered robots,
bases, grippers or motors, by name, with their size and spec file), ``assembler inspect`` (every
joint parameter and actuator of a robot and where each value came from) and ``assembler diff A B``
(what changed between two specs, in the spec and in the compiled model; or between two lock files,
``robot-assembler.lock@HEAD robot-assembler.lock``, robot by robot).

``list`` shows a motor's gear ratio, torque limit and reflected inertia with its own gearbox. Spec
files are shown short: relative to the working directory when below it, and shipped specs as
``specs/...`` (where they sit in a checkout) even when read from an installed package's
``site-packages/assembler/_shipped/specs``, marked ``(shipped)``: a lab's own ``specs/`` folder
reads the same, and a reader must tell the project's specs from the lab's.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Mapping
from pathlib import Path
from typing import TypeVar

from assembler.cli.common import bare_robot, override_flags, table
from assembler.errors import AssemblerError, MissingPackageError
from assembler.files.paths import display_path, shipped_specs_dir
from assembler.models import PartModel
from assembler.models.actuator_table import ActuatorRecord
from assembler.models.motor_joints import derivation_lines
from assembler.models.motor_rules import Drive
from assembler.models.motor_table import MOTORS
from assembler.models.physical import PhysicalTable
from assembler.registry.lookup import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS
from assembler.registry.packs import pack_of
from assembler.spec.schema import JOINT_RULE_ATTRIBUTES, JointMotor
from assembler.tools.diff import FORMATS, compare
from assembler.tools.diff.revision import text_at
from assembler.tools.lock import Lock, lock_changes, parse_lock, read_lock


def _dof_text(cls: type[PartModel]) -> str:
    try:
        return str(cls(idn=0).dof_joints)
    except MissingPackageError as error:
        return f"? ({error.package or 'a package'} not installed)"
    except AssemblerError:
        return "? (invalid: run assembler validate)"


def short_path(path: Path) -> str:
    """A spec file as a user reads it: below the working directory, ``specs/...`` when shipped, then
    marked ``(shipped)``, or ``PACK:file (pack DISTRIBUTION VERSION)`` when an installed pack's."""
    shipped = shipped_specs_dir().resolve()
    if path.is_relative_to(shipped):
        shown = display_path(path)
        short = (
            shown if not Path(shown).is_absolute() else str(Path(shipped.name) / path.relative_to(shipped))
        )
        return f"{short} (shipped)"
    pack = pack_of(path)
    if pack is not None:
        return f"{pack.name}:{path.resolve().relative_to(pack.folder).as_posix()} ({pack.label})"
    return display_path(path)


def _source(cls: type[PartModel]) -> str:
    loaded = cls.loaded
    if loaded is None:
        return cls.__module__
    path = loaded.document.path
    return short_path(path) if path is not None else loaded.document.file


P = TypeVar("P", bound=PartModel)


def _by_name(registry: Mapping[str, type[P]]) -> list[tuple[str, type[P]]]:
    """Entries sorted by name as people sort them (``GR1`` before ``Gx``, ``iiwa`` beside ``IIWA``)."""
    return sorted(registry.items(), key=lambda item: (item[0].casefold(), item[0]))


def run_list(args: argparse.Namespace) -> int:
    if args.what == "bases":
        rows: list[tuple[str, ...]] = [("base", "type", "joints", "spec")]
        for name, base in _by_name(REGISTERED_BASES):
            rows.append((name, base.spec.type, _dof_text(base), _source(base)))
    elif args.what == "motors":
        rows = [("motor", "gear ratio", "torque limit (N m)", "armature (kg m2)", "spec")]
        for name in sorted(MOTORS.names(), key=str.casefold):
            loaded = MOTORS.lookup(name)
            drive = Drive(loaded.spec, JointMotor(match="*", motor=name), 0)
            limit, armature = drive.torque_limit(), drive.armature()
            path = loaded.document.path
            rows.append(
                (
                    name,
                    f"{loaded.spec.gear_ratio:g}",
                    f"{limit.value:.4g}" if limit is not None else "-",
                    f"{armature.value:.4g}" if armature is not None else "-",
                    short_path(path) if path is not None else loaded.document.file,
                )
            )
    elif args.what == "grippers":
        rows = [("gripper", "joints", "spec")]
        for name, gripper in _by_name(REGISTERED_GRIPPERS):
            rows.append((name, _dof_text(gripper), _source(gripper)))
    else:
        rows = [("robot", "morphology", "dof", "spec")]
        for name, robot in _by_name(REGISTERED_ROBOTS):
            rows.append((name, robot.spec.morphology, _dof_text(robot), _source(robot)))
    print(table(rows))
    return 0


def run_inspect(args: argparse.Namespace) -> int:
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


def _lock(reference: str) -> Lock:
    """A lock file, or ``FILE@REV`` for its text at a git revision."""
    path, _, revision = reference.rpartition("@") if "@" in reference else (reference, "", "")
    if revision:
        return parse_lock(text_at(Path(path), revision), reference)
    return read_lock(Path(reference))


def run_diff(args: argparse.Namespace) -> int:
    if all(reference.partition("@")[0].endswith(".lock") for reference in (args.before, args.after)):
        lines = lock_changes(_lock(args.before), _lock(args.after))  # a lock change, robot by robot
        sys.stdout.write("".join(line + "\n" for line in lines) or "the locks are the same\n")
        return 1 if args.exit_code and lines else 0
    comparison = compare(args.before, args.after)
    sys.stdout.write(FORMATS[args.format](comparison))
    return 1 if args.exit_code and not comparison.identical else 0
