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

from assembler.catalog import add_spec_folders, register_specs
from assembler.errors import AssemblerError, Problem
from assembler.loader import SPEC_SUFFIXES
from assembler.mjcf.emit import bundle
from assembler.models import RobotModel
from assembler.paths import display_path
from assembler.registry import REGISTERED_ROBOTS, create_robot
from assembler.schema import JOINT_RULE_ATTRIBUTES, RobotSpec


def _robot(reference: str, idn: int) -> RobotModel:
    """A robot by registered name, or from a spec file given as a path."""
    if reference.endswith(SPEC_SUFFIXES) or Path(reference).is_file():
        (cls, *_) = register_specs(reference)
        return cls(idn=idn)
    return create_robot(reference, idn=idn)


def _table(rows: Sequence[Sequence[str]]) -> str:
    """Rows as left-aligned columns, two spaces apart."""
    widths = [max(len(row[i]) for row in rows) for i in range(len(rows[0]))]
    return "\n".join(
        "  ".join(cell.ljust(width) for cell, width in zip(row, widths, strict=True)).rstrip() for row in rows
    )


def _dof_text(cls: type[RobotModel]) -> str:
    try:
        return str(cls(idn=0).dof)
    except AssemblerError as error:
        return f"? ({error.problems[0].message})"


def command_list(args: argparse.Namespace) -> int:
    rows: list[tuple[str, ...]] = [("robot", "morphology", "dof", "spec")]
    for name, cls in REGISTERED_ROBOTS.items():
        loaded = cls.loaded
        source = display_path(loaded.document.file) if loaded is not None else cls.__module__
        rows.append((name, cls.spec.morphology, _dof_text(cls), source))
    print(_table(rows))
    return 0


def command_validate(args: argparse.Namespace) -> int:
    classes = register_specs(*args.paths)
    problems: list[Problem] = []
    for cls in classes:
        try:
            robot = cls(idn=0)
            if args.compile:
                robot.get_model()
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise AssemblerError(problems)
    what = "validated and compiled" if args.compile else "valid"
    print(f"{len(classes)} spec(s) {what}: {', '.join(c.__name__ for c in classes)}")
    return 0


def command_build(args: argparse.Namespace) -> int:
    robot = _robot(args.robot, args.idn)
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


def robot_spec_json_schema() -> dict[str, object]:
    """The JSON Schema of robot spec files, as editors and review bots consume it."""
    schema = RobotSpec.model_json_schema()
    return {"$schema": "https://json-schema.org/draft/2020-12/schema", **schema}


def command_schema(args: argparse.Namespace) -> int:
    print(json.dumps(robot_spec_json_schema(), indent=2))
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

    listing = commands.add_parser("list", help="registered robots with morphology and dof")
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
    build.set_defaults(run=command_build)

    inspect = commands.add_parser("inspect", help="joint parameters and where each value came from")
    inspect.add_argument("robot", help="registered robot name or spec file")
    inspect.add_argument("--idn", type=int, default=0)
    inspect.add_argument("--format", choices=("text", "json"), default="text")
    inspect.set_defaults(run=command_inspect)

    schema = commands.add_parser("schema", help="print the JSON Schema of robot specs")
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
