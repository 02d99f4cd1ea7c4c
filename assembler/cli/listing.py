"""``assembler list``: the registered robots, bases or grippers, with their size and spec file."""

from __future__ import annotations

import argparse

from assembler.cli.common import table
from assembler.errors import AssemblerError, MissingPackageError
from assembler.models import PartModel
from assembler.paths import display_path
from assembler.registry import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS


def _dof_text(cls: type[PartModel]) -> str:
    try:
        return str(cls(idn=0).dof_joints)
    except MissingPackageError as error:
        return f"? ({error.package or 'a package'} not installed)"
    except AssemblerError:
        return "? (invalid: run assembler validate)"


def _source(cls: type[PartModel]) -> str:
    loaded = cls.loaded
    return display_path(loaded.document.file) if loaded is not None else cls.__module__


def run(args: argparse.Namespace) -> int:
    if args.what == "bases":
        rows: list[tuple[str, ...]] = [("base", "type", "joints", "spec")]
        for name, base in REGISTERED_BASES.items():
            rows.append((name, base.spec.type, _dof_text(base), _source(base)))
    elif args.what == "grippers":
        rows = [("gripper", "joints", "spec")]
        for name, gripper in REGISTERED_GRIPPERS.items():
            rows.append((name, _dof_text(gripper), _source(gripper)))
    else:
        rows = [("robot", "morphology", "dof", "spec")]
        for name, robot in REGISTERED_ROBOTS.items():
            rows.append((name, robot.spec.morphology, _dof_text(robot), _source(robot)))
    print(table(rows))
    return 0
