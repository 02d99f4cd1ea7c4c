"""``assembler list``: the registered robots, bases, grippers or motors, by name, with their size (a
motor: its gear ratio, torque limit and reflected inertia with its own gearbox) and spec file.

Spec files are shown short: relative to the working directory when below it, and shipped specs
as ``specs/...`` (where they sit in a checkout) even when read from an installed package's
``site-packages/assembler/_shipped/specs``, marked ``(shipped)``: a lab's own ``specs/`` folder
reads the same, and a reader must tell the project's specs from the lab's.
"""

from __future__ import annotations

import argparse
from collections.abc import Mapping
from pathlib import Path
from typing import TypeVar

from assembler.cli.common import table
from assembler.errors import AssemblerError, MissingPackageError
from assembler.files.paths import display_path, shipped_specs_dir
from assembler.models import PartModel
from assembler.models.motor_rules import Drive
from assembler.models.motor_table import MOTORS
from assembler.registry.lookup import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS
from assembler.registry.packs import pack_of
from assembler.spec.schema import JointMotor


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


def run(args: argparse.Namespace) -> int:
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
