"""What the commands share: running one parsed command (the user's spec folders and allowed paths
first, then the function :data:`~assembler.cli.arguments.COMMANDS` names, its module imported now, so
``assembler --help`` never pays for it), finding a robot from a name or a spec file, the build flags,
and printing aligned tables."""

from __future__ import annotations

import argparse
import importlib
from collections.abc import Sequence

from assembler.errors import AssemblerError
from assembler.files.inputs import note_inputs
from assembler.files.paths import allowing
from assembler.models import PartModel, RobotModel
from assembler.registry.catalog import add_spec_folders, register_with_siblings
from assembler.registry.instances import assemble, create_base, create_gripper, create_robot
from assembler.registry.lookup import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS, robot_class
from assembler.spec.documents import Override, parse_overrides
from assembler.spec.part_arguments import DEFAULT, is_spec_file
from assembler.worlds.variants.effects import overrides_without_effect, superseded


def run_command(args: argparse.Namespace) -> int:
    """Carry out the command ``args`` names and return its exit code."""
    with allowing(args.allow_path):
        add_spec_folders(args.specs)
        command = getattr(importlib.import_module(args.module), args.function)
        return int(command(args))


def robot_name(reference: str) -> str:
    """A registered robot name, registering the spec first when given a spec file path."""
    if is_spec_file(reference):
        registered = register_with_siblings([reference])
        if not registered:  # a folder named like a spec file
            raise AssemblerError(f"{reference}: no spec in it; give a spec file or a robot name")
        return registered[0].__name__
    return reference


def bare_robot(reference: str, idn: int, changes: Sequence[Override] = ()) -> RobotModel:
    """A robot alone (no base, no grippers), by registered name or spec file, with overrides."""
    return create_robot(robot_name(reference), idn=idn, overrides=changes)


def override_flags(args: argparse.Namespace) -> list[Override]:
    """The ``--set`` flags, parsed (a bad one is an error naming the flag)."""
    return parse_overrides(getattr(args, "overrides", None) or [], label="--set ")


def gripper_choices(values: list[str]) -> dict[str, str | None]:
    """``--gripper ARM=NAME`` flags as a mapping (``none`` means no gripper on that arm)."""
    choices: dict[str, str | None] = {}
    for value in values:
        arm, sep, name = value.partition("=")
        if not sep or not arm or not name:
            raise AssemblerError(
                f"--gripper expects ARM=NAME (e.g. right=PincerGripper or left=none), got '{value}'"
            )
        choices[arm] = None if name.lower() == "none" else name
    return choices


def assembled(args: argparse.Namespace, overrides: Sequence[Override] | None = None) -> RobotModel:
    """The robot the assembly flags describe: its default base and grippers unless they say otherwise
    (with ``overrides`` instead of the ``--set`` flags when given)."""
    name = robot_name(args.robot)
    base = None if args.no_base else (args.base or DEFAULT)
    grippers = gripper_choices(args.gripper)
    if args.no_grippers:
        arms = getattr(robot_class(name).spec, "arms", ())
        grippers = {arm: None for arm in arms}
    changes = override_flags(args) if overrides is None else overrides
    robot = assemble(name, idn=args.idn, base=base, grippers=grippers, overrides=changes)
    note_inputs(spec_files(robot))
    return robot


def part_alone(args: argparse.Namespace) -> PartModel | None:
    """The gripper or base ``args.robot`` names, made alone (``assembler build hand.yaml``, ``render``);
    None when it names a robot or nothing registered (the robot path then says what it knows)."""
    name = robot_name(args.robot)
    if name in REGISTERED_ROBOTS:
        return None
    if name in REGISTERED_GRIPPERS:
        return create_gripper(name, idn=args.idn)
    if name in REGISTERED_BASES:
        return create_base(name, idn=args.idn)
    return None


def spec_files(robot: RobotModel) -> list[str]:
    """Every spec file the robot, its base and grippers were made from (parents included)."""
    parts = [type(robot), *(type(part) for part in robot.models)]
    documents = [getattr(getattr(part, "loaded", None), "document", None) for part in parts]
    return [origin[0] for document in documents for origin in getattr(document, "origins", ())]


def idle_override_warnings(args: argparse.Namespace) -> list[str]:
    """A warning line per ``--set`` field given more than once (only the last counts), and per
    ``--set`` that changes nothing in the compiled model."""
    overrides = override_flags(args)
    idle = overrides_without_effect(lambda changes: assembled(args, changes), overrides, use_cache(args))
    replaced = {id(override) for override, gone in zip(overrides, superseded(overrides), strict=True) if gone}
    repeats: dict[str, int] = {}
    for override in overrides:
        repeats[override.key] = repeats.get(override.key, 0) + 1
    lines = []
    for key, count in repeats.items():
        if count > 1:
            lines.append(f"warning: --set {key} is given {count} times; only the last counts")
    for override in idle:
        if id(override) in replaced and repeats[override.key] == 1:  # replaced by a field containing it
            lines.append(
                f"warning: --set {override.key} is replaced by a later --set of a field containing it"
            )
        elif id(override) not in replaced:
            lines.append(
                f"warning: {override.label}{override.key} changes nothing in the compiled model; "
                "see what else in the spec sets it"
            )
    return lines


def use_cache(args: argparse.Namespace) -> bool:
    """False when the command was given ``--no-cache``."""
    return not getattr(args, "no_cache", False)


def table(rows: Sequence[Sequence[str]]) -> str:
    """Rows as left-aligned columns, two spaces apart."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return "\n".join(
        "  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip() for row in rows
    )
