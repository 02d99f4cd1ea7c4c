"""``assembler lint``: problems MuJoCo accepts silently, each with a code, severity, subject, why and fix.

Takes robots (with the usual assembly flags), spec files and spec folders; bases and grippers are
linted on their own. Exit code 1 when any finding is an error or a spec does not load.
"""

from __future__ import annotations

import argparse
import json
from collections import Counter
from collections.abc import Sequence

from assembler.cli.common import assembled, use_cache
from assembler.cli.report import github_annotation, location_fields, print_problems
from assembler.errors import AssemblerError, Problem
from assembler.models import PartModel
from assembler.registry.catalog import classes_named
from assembler.tools.lint import SEVERITIES, Finding, LintTarget, lint, part_target, robot_target


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


def run(args: argparse.Namespace) -> int:
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
