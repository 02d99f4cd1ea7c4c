"""The ``assembler`` command: parse arguments, call the API, print, return an exit code.

Exit codes: 0 success, 1 a problem in the user's input (printed one line per problem, no
traceback), 2 a usage error (argparse's own).
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Sequence
from pathlib import Path

from pydantic.json_schema import models_json_schema

from assembler.assembly import DEFAULT, assemble
from assembler.catalog import add_spec_folders, register_specs
from assembler.errors import AssemblerError, MissingPackageError, Problem
from assembler.loader import SPEC_SUFFIXES
from assembler.mjcf.emit import bundle, to_xml, write_atomically
from assembler.models import PartModel, RobotModel
from assembler.paths import display_path
from assembler.registry import (
    REGISTERED_BASES,
    REGISTERED_GRIPPERS,
    REGISTERED_ROBOTS,
    create_robot,
    robot_class,
)
from assembler.scene import load_scene
from assembler.schema import JOINT_RULE_ATTRIBUTES, BaseSpec, GripperSpec, RobotSpec, SceneSpec


def _robot_name(reference: str) -> str:
    """A registered robot name, registering the spec first when given a spec file path."""
    if reference.endswith(SPEC_SUFFIXES) or Path(reference).is_file():
        (cls, *_) = register_specs(reference)
        return cls.__name__
    return reference


def _robot(reference: str, idn: int) -> RobotModel:
    """A robot alone (no base, no grippers), by registered name or spec file."""
    return create_robot(_robot_name(reference), idn=idn)


def _gripper_choices(values: list[str]) -> dict[str, str | None]:
    choices: dict[str, str | None] = {}
    for value in values:
        arm, sep, name = value.partition("=")
        if not sep or not arm or not name:
            raise AssemblerError(
                f"--gripper expects ARM=NAME (e.g. right=PincerGripper or left=none), got '{value}'"
            )
        choices[arm] = None if name.lower() == "none" else name
    return choices


def _assembled(args: argparse.Namespace) -> RobotModel:
    """The robot of ``build``: with its default base and grippers unless the flags say otherwise."""
    name = _robot_name(args.robot)
    base = None if args.no_base else (args.base or DEFAULT)
    grippers = _gripper_choices(args.gripper)
    if args.no_grippers:
        arms = getattr(robot_class(name).spec, "arms", ())
        grippers = {arm: None for arm in arms}
    return assemble(name, idn=args.idn, base=base, grippers=grippers)


def _table(rows: Sequence[Sequence[str]]) -> str:
    """Rows as left-aligned columns, two spaces apart."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return "\n".join(
        "  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip() for row in rows
    )


def _dof_text(cls: type[PartModel]) -> str:
    try:
        return str(cls(idn=0).dof_joints)
    except MissingPackageError:
        return "? (robosuite not installed)"
    except AssemblerError:
        return "? (invalid: run assembler validate)"


def _source(cls: type[PartModel]) -> str:
    loaded = cls.loaded
    return display_path(loaded.document.file) if loaded is not None else cls.__module__


def command_list(args: argparse.Namespace) -> int:
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
    print(_table(rows))
    return 0


def command_validate(args: argparse.Namespace) -> int:
    classes = register_specs(*args.paths)
    problems: list[Problem] = []
    unchecked: list[str] = []
    missing = ""
    for cls in classes:
        try:
            part = cls(idn=0)
            if args.compile:
                if isinstance(part, RobotModel):
                    assemble(cls.__name__, idn=0).get_model()  # with its default base and grippers
                else:
                    part.compile_alone()
        except MissingPackageError as error:
            unchecked.append(cls.__name__)
            missing = error.problems[0].message.split(": ", 1)[-1]
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise AssemblerError(problems)
    if unchecked:
        print(f"note: {len(unchecked)} spec(s) checked without their MJCF ({missing})", file=sys.stderr)
    what = "validated and compiled" if args.compile else "valid"
    print(f"{len(classes)} spec(s) {what}: {', '.join(c.__name__ for c in classes)}")
    return 0


def command_build(args: argparse.Namespace) -> int:
    robot = _assembled(args)
    if args.bundle:
        name = Path(args.output).name if args.output else f"{type(robot).__name__}.xml"
        robot.get_model()  # compile first: a robot that does not compile writes nothing
        target = bundle(robot.mjspec, Path(args.bundle), name)
        print(f"wrote {display_path(target)} with its assets", file=sys.stderr)
    elif args.output:
        target = robot.save(args.output)
        print(f"wrote {display_path(target)}", file=sys.stderr)
    else:
        sys.stdout.write(robot.get_xml())
    return 0


def command_inspect(args: argparse.Namespace) -> int:
    robot = _robot(args.robot, args.idn)
    if args.format == "json":
        table = {
            robot.naming_prefix + joint: {
                a: {"value": v.value, "source": v.source} for a, v in values.items()
            }
            for joint, values in robot.joint_values.items()
        }
        print(json.dumps({"robot": type(robot).__name__, "dof": robot.dof, "joints": table}, indent=2))
        return 0
    loaded = type(robot).loaded
    print(f"{type(robot).__name__}: {robot.spec.morphology}, {robot.dof} dof, prefix {robot.naming_prefix}")
    if loaded is not None:
        print(f"spec: {loaded.source}")
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
    print(_table(rows))
    return 0


def spec_json_schema() -> dict[str, object]:
    """The JSON Schema of every spec file (robot, base, gripper, scene), for editors and review bots."""
    models = (RobotSpec, BaseSpec, GripperSpec, SceneSpec)
    _, schema = models_json_schema([(m, "validation") for m in models], ref_template="#/$defs/{model}")
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "robot-assembler spec",
        "description": "A robot, base, gripper or scene spec; `kind` says which (robot if absent).",
        "anyOf": [{"$ref": f"#/$defs/{m.__name__}"} for m in models],
        **schema,
    }


def command_scene(args: argparse.Namespace) -> int:
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


def command_schema(args: argparse.Namespace) -> int:
    print(json.dumps(spec_json_schema(), indent=2))
    return 0


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="assembler", description="Assemble MuJoCo robots from declarative YAML specs."
    )
    parser.add_argument(
        "--specs",
        action="append",
        default=[],
        metavar="DIR",
        help="also register the specs in DIR (repeatable)",
    )
    commands = parser.add_subparsers(dest="command", required=True)

    listing = commands.add_parser("list", help="registered robots (or bases, grippers)")
    listing.add_argument("what", nargs="?", choices=("robots", "bases", "grippers"), default="robots")
    listing.set_defaults(run=command_list)

    validate = commands.add_parser("validate", help="check spec files and folders")
    validate.add_argument("paths", nargs="+", help="spec files or folders")
    validate.add_argument("--compile", action="store_true", help="also compile each robot with MuJoCo")
    validate.set_defaults(run=command_validate)

    build = commands.add_parser("build", help="write a robot's standalone MJCF")
    build.add_argument("robot", help="registered robot name or spec file")
    build.add_argument("--idn", type=int, default=0, help="instance number (prefix robot{idn}_)")
    build.add_argument("-o", "--output", help="output XML file (default: standard output)")
    build.add_argument("--bundle", metavar="DIR", help="write the XML and copies of its assets to DIR")
    build.add_argument("--base", help="a registered base instead of the robot's default")
    build.add_argument("--no-base", action="store_true", help="no base at all")
    build.add_argument(
        "--gripper",
        action="append",
        default=[],
        metavar="ARM=NAME",
        help="gripper per arm (NAME may be none)",
    )
    build.add_argument("--no-grippers", action="store_true", help="no grippers on any arm")
    build.set_defaults(run=command_build)

    scene = commands.add_parser("scene", help="several placed robots in one MJCF")
    scene.add_argument("scene", help="scene YAML file")
    scene.add_argument("-o", "--output", help="output XML file (default: standard output)")
    scene.set_defaults(run=command_scene)

    inspect = commands.add_parser("inspect", help="joint parameters and where each value came from")
    inspect.add_argument("robot", help="registered robot name or spec file")
    inspect.add_argument("--idn", type=int, default=0)
    inspect.add_argument("--format", choices=("text", "json"), default="text")
    inspect.set_defaults(run=command_inspect)

    schema = commands.add_parser("schema", help="print the JSON Schema of spec files")
    schema.set_defaults(run=command_schema)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    try:
        add_spec_folders(args.specs)
        return int(args.run(args))
    except AssemblerError as error:
        for problem in error.problems:
            print(str(problem), file=sys.stderr)
        return 1


if __name__ == "__main__":
    sys.exit(main())
