"""``assembler validate``: check spec files and folders (schema, names, optionally a compile), and the
repository's lock (``--locked``); ``assembler lock`` writes that lock (:mod:`assembler.tools.lock`).

The summary counts what was done to each spec: validated against its model file (and compiled, with
``--compile``), or only validated because the package holding its model file is not installed (one
line per missing package, with the specs it leaves unchecked and what to install).
"""

from __future__ import annotations

import argparse
import sys

from assembler.cli.report import print_problems
from assembler.errors import AssemblerError
from assembler.files.paths import display_path
from assembler.tools.lock import check_locked, write_lock
from assembler.tools.validate import ValidationReport, validate_specs


def summary(report: ValidationReport, compiled: bool) -> list[str]:
    """One line per outcome with its count and names, e.g. ``12 spec(s) validated and compiled: ...``."""
    unchecked = set(report.unchecked)
    checked = [cls.__name__ for cls in report.classes if cls.__name__ not in unchecked]
    lines = []
    if checked or not (unchecked or report.placements or report.motors):
        what = "validated and compiled" if compiled else "valid"
        lines.append(f"{len(checked)} spec(s) {what}: {', '.join(checked)}")
    for package in report.missing.values():
        lines.append(
            f"{len(package.specs)} spec(s) valid but not checked against their model file"
            f"{' nor compiled' if compiled else ''}: {', '.join(package.specs)}"
        )
        lines.append(f"    because: {package.message}")
    if report.motors:
        lines.append(f"{len(report.motors)} motor spec(s) valid: {', '.join(report.motors)}")
    if report.placements:
        files = ", ".join(report.placements)
        lines.append(f"{len(report.placements)} scene and experiment file(s) valid: {files}")
    return lines


def lock(args: argparse.Namespace) -> int:
    target, written = write_lock(args.paths)
    count = sum(len(robot.files) for robot in written.robots.values())
    robots = f"{len(written.robots)} robot{'s' if len(written.robots) != 1 else ''}"
    print(f"wrote {display_path(target)}: {count} files of {robots}", file=sys.stderr)
    return 0


def run(args: argparse.Namespace) -> int:
    if args.command == "lock":
        return lock(args)
    lines: list[str] = []
    try:
        paths = args.paths or args.specs
        if args.locked:
            path, count = check_locked()
            lines.append(f"{display_path(path)}: the {count} files it lists are unchanged")
        elif not paths:
            raise AssemblerError("validate: give spec files or folders (or --specs DIR)")
        if paths:
            lines = summary(validate_specs(paths, compile=args.compile), args.compile) + lines
    except AssemblerError as error:  # printed in the chosen format (GitHub annotations in CI)
        print_problems(error.problems, args.format)
        return 1
    print("\n".join(lines))
    return 0
