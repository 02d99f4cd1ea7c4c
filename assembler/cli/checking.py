"""The commands that check specs, and how they report: ``assembler validate`` (schema, names, optionally
a compile, and the repository's lock with ``--locked``) and ``assembler lock`` (writes that lock:
:mod:`assembler.tools.lock`); ``assembler lint`` (problems MuJoCo accepts silently, each with a
code, severity, subject, why and fix); ``assembler schema`` (the JSON Schema of every spec kind, for
editors and review bots, or with ``--markdown`` the spec reference generated from it,
``docs/spec.md``).

Problems and findings are reported one way for ``validate`` and ``lint``: plain lines, JSON, or with
``--format github`` GitHub Actions workflow commands (``::error file=F,line=L,col=C::msg``), which
GitHub shows as annotations on the pull request's files.

The validate summary counts what was done to each spec: validated against its model file (and
compiled, with ``--compile``), or only validated because the package holding its model file is not
installed (one line per missing package, with the specs it leaves unchecked and what to install).
Lint takes robots (with the usual assembly flags), spec files and spec folders; bases and grippers
are linted on their own. Its exit code is 1 when any finding is an error or a spec does not load.
"""

from __future__ import annotations

import argparse
import json
import sys
from collections import Counter
from collections.abc import Sequence

from assembler.cli.common import assembled, use_cache
from assembler.errors import AssemblerError, Location, Problem
from assembler.files.paths import display_path
from assembler.models import PartModel
from assembler.registry.catalog import classes_named
from assembler.spec.schema.json_schema import schema_text
from assembler.tools.lint import SEVERITIES, Finding, LintTarget, lint, part_target, robot_target
from assembler.tools.lock import check_locked, write_lock
from assembler.tools.validate import ValidationReport, validate_specs

GITHUB_LEVELS: dict[str, str] = {"error": "error", "warning": "warning", "info": "notice"}
"""Our severities as GitHub's annotation levels."""


def _escape_data(text: str) -> str:
    # GitHub's toolkit escapes these so that a message stays one command on one line.
    return text.replace("%", "%25").replace("\r", "%0D").replace("\n", "%0A")


def _escape_property(text: str) -> str:
    return _escape_data(text).replace(":", "%3A").replace(",", "%2C")


def github_annotation(
    severity: str, message: str, location: Location | None = None, title: str | None = None
) -> str:
    """One workflow command, e.g. ``::warning file=a.yaml,line=3,col=5,title=RA301::message``."""
    properties = []
    if location is not None:
        properties.append(f"file={_escape_property(location.file)}")
        if location.line is not None:
            properties.append(f"line={location.line}")
            if location.column is not None:
                properties.append(f"col={location.column}")
    if title:
        properties.append(f"title={_escape_property(title)}")
    level = GITHUB_LEVELS.get(severity, "error")
    head = f"::{level} {','.join(properties)}" if properties else f"::{level}"
    return f"{head}::{_escape_data(message)}"


def location_fields(location: Location | None) -> dict[str, object]:
    """A location as JSON fields (file, line, column; null where unknown)."""
    if location is None:
        return {"file": None, "line": None, "column": None}
    return {"file": location.file, "line": location.line, "column": location.column}


def print_problems(problems: Sequence[Problem], output_format: str) -> None:
    """Problems with the user's input: one line each (text, on stderr), JSON, or GitHub errors."""
    if output_format == "github":
        for problem in problems:
            message = f"{problem.path}: {problem.message}" if problem.path else problem.message
            print(github_annotation("error", message, problem.location))
    elif output_format == "json":
        items = [
            {"severity": "error", "path": p.path, "message": p.message, **location_fields(p.location)}
            for p in problems
        ]
        print(json.dumps({"problems": items}, indent=2))
    else:
        for problem in problems:
            print(str(problem), file=sys.stderr)


def validation_summary(report: ValidationReport, compiled: bool) -> list[str]:
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


def run_lock(args: argparse.Namespace) -> int:
    target, written = write_lock(args.paths)
    count = sum(len(robot.files) for robot in written.robots.values())
    robots = f"{len(written.robots)} robot{'s' if len(written.robots) != 1 else ''}"
    print(f"wrote {display_path(target)}: {count} files of {robots}", file=sys.stderr)
    return 0


def run_validate(args: argparse.Namespace) -> int:
    lines: list[str] = []
    try:
        paths = args.paths or args.specs
        if args.locked:
            path, count = check_locked()
            lines.append(f"{display_path(path)}: the {count} files it lists are unchanged")
        elif not paths:
            raise AssemblerError("validate: give spec files or folders (or --specs DIR)")
        if paths:
            lines = validation_summary(validate_specs(paths, compile=args.compile), args.compile) + lines
    except AssemblerError as error:  # printed in the chosen format (GitHub annotations in CI)
        print_problems(error.problems, args.format)
        return 1
    print("\n".join(lines))
    return 0


def _target(cls: type[PartModel], args: argparse.Namespace) -> LintTarget:
    name = cls.__name__
    if cls.family == "robot":
        robot = assembled(argparse.Namespace(**{**vars(args), "robot": name}))
        return robot_target(robot, name, cache=use_cache(args))
    return part_target(cls(idn=args.idn), name)


def _counts(findings: Sequence[Finding]) -> str:
    counts = Counter(f.severity for f in findings if f.acknowledged is None)
    parts = [f"{counts[s]} {s}{'s' if counts[s] != 1 else ''}" for s in SEVERITIES if counts[s]]
    acknowledged = sum(f.acknowledged is not None for f in findings)
    if acknowledged:
        parts.append(f"{acknowledged} acknowledged")
    return ", ".join(parts) or "no findings"


def _print_text(name: str, findings: Sequence[Finding]) -> None:
    for finding in findings:
        where = str(finding.location) if finding.location else name
        marker = "acknowledged " if finding.acknowledged is not None else ""
        print(f"{where}: {marker}{finding.severity} {finding.code} {finding.subject}: {finding.why}")
        if finding.acknowledged is not None:
            print(f"    acknowledged: {finding.acknowledged}")
        else:
            print(f"    fix: {finding.fix}")
    print(f"{name}: {_counts(findings)}")


def _print_github(name: str, findings: Sequence[Finding]) -> None:
    for finding in findings:
        if finding.acknowledged is not None:
            message = f"{finding.subject}: {finding.why}. Acknowledged: {finding.acknowledged}"
            print(github_annotation("info", message, finding.location, f"{finding.code} ({name})"))
            continue
        message = f"{finding.subject}: {finding.why}. Fix: {finding.fix}"
        print(github_annotation(finding.severity, message, finding.location, f"{finding.code} ({name})"))


def _as_json(finding: Finding) -> dict[str, object]:
    return {
        "code": finding.code,
        "severity": finding.severity,
        "subject": finding.subject,
        "why": finding.why,
        "fix": finding.fix,
        "acknowledged": finding.acknowledged,
        **location_fields(finding.location),
    }


def run_lint(args: argparse.Namespace) -> int:
    try:
        classes = classes_named([args.robot, *args.more])
    except AssemblerError as error:
        print_problems(error.problems, args.format)
        return 1
    results: list[tuple[str, list[Finding]]] = []
    problems: list[Problem] = []
    for cls in classes:
        try:
            findings = lint(_target(cls, args), args.target)
        except AssemblerError as error:  # a part that does not assemble: reported like validate does
            problems.extend(error.problems)
            continue
        results.append((cls.__name__, findings))
        if args.format == "text":
            _print_text(cls.__name__, findings)
        elif args.format == "github":
            _print_github(cls.__name__, findings)
    if args.format == "json":
        targets = [{"name": name, "findings": [_as_json(f) for f in found]} for name, found in results]
        problem_items = [{"message": str(p), **location_fields(p.location)} for p in problems]
        print(json.dumps({"targets": targets, "problems": problem_items}, indent=2))
    elif problems:
        print_problems(problems, args.format)
    failed = bool(problems) or any(f.fails for _, found in results for f in found)
    return 1 if failed else 0


def run_schema(args: argparse.Namespace) -> int:
    sys.stdout.write(schema_text(markdown=args.markdown))
    return 0
