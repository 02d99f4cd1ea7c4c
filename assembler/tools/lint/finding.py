"""A lint finding: what is wrong, how bad it is, with what, why it matters and how to fix it."""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

from assembler.errors import Location

Severity = Literal["error", "warning", "info"]

SEVERITIES: tuple[Severity, ...] = ("error", "warning", "info")
"""Worst first: errors make ``assembler lint`` exit non-zero; warnings and infos do not."""


@dataclass(frozen=True)
class Finding:
    """One problem MuJoCo accepts silently, e.g. ``RA301 warning robot0_act7: ctrlrange exceeds ...``."""

    code: str
    """Stable identifier of the check, e.g. RA301 (see :data:`assembler.tools.lint.CHECKS`)."""

    severity: Severity
    """error, warning or info."""

    subject: str
    """The element concerned, as named in the assembled model (body, joint, geom or actuator)."""

    why: str
    """What is wrong, with the numbers that show it."""

    fix: str
    """What to change, and where."""

    location: Location | None = None
    """Where to change it: the spec field or the MJCF element, when known."""

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        return f"{where}{self.severity} {self.code} {self.subject}: {self.why}"
