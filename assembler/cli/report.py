"""How commands report problems and findings: plain lines, JSON, or GitHub annotations.

``--format github`` prints GitHub Actions workflow commands (``::error file=F,line=L,col=C::msg``),
which GitHub shows as annotations on the pull request's files. One implementation, used by
``validate`` and ``lint``.
"""

from __future__ import annotations

import json
import sys
from collections.abc import Sequence

from assembler.errors import Location, Problem

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
