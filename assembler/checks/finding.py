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

    acknowledged: str | None = None
    """The reason a spec gives for accepting this finding (``lint.acknowledge``); None when none does.
    An acknowledged finding is still reported, and never fails lint."""

    @property
    def fails(self) -> bool:
        """Whether the finding makes ``assembler lint`` exit non-zero: an error nobody acknowledged."""
        return self.severity == "error" and self.acknowledged is None

    def __str__(self) -> str:
        where = f"{self.location}: " if self.location else ""
        marker = "acknowledged " if self.acknowledged is not None else ""
        text = f"{where}{marker}{self.severity} {self.code} {self.subject}: {self.why}"
        return text + (f" (acknowledged: {self.acknowledged})" if self.acknowledged is not None else "")
