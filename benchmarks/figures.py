"""One measured figure: ours against a reference, as a ratio, with the issue's target and whether
it was met. Printed as each figure is measured, and collected for the JSON and Markdown reports."""

from __future__ import annotations

import math
from dataclasses import asdict, dataclass
from typing import Any


def seconds_text(seconds: float) -> str:
    """``12.3 ms`` or ``1.24 s``."""
    if math.isnan(seconds):
        return "-"
    return f"{seconds * 1000:.1f} ms" if seconds < 1 else f"{seconds:.2f} s"


@dataclass(frozen=True)
class Figure:
    """Ours against a reference for one subject (a robot, a scene size, start-up)."""

    measure: str
    """assemble, cold load, warm load, repeated load, scale or start-up."""

    subject: str
    """What was measured: a robot name, ``N=32``, ``import``."""

    ours: float
    """Our time (seconds)."""

    reference_name: str
    """What we compare with, e.g. ``robosuite`` or ``MuJoCo compile``."""

    reference: float
    """The reference's time (seconds)."""

    ratio: float
    """The figure the target is about (usually ours / reference; a speed-up where it says so)."""

    target: str
    """The issue's target, e.g. ``<= 0.5x``; empty when the issue sets none."""

    met: bool | None
    """Whether the target was met (None without a target)."""

    note: str = ""
    """Anything a reader needs to read the figure right."""

    unit: str = "s"
    """What ``ours`` and ``reference`` count: seconds, or ``instructions`` (valgrind's callgrind)."""

    def amount(self, value: float) -> str:
        """``value`` in this figure's unit, as a reader reads it."""
        return seconds_text(value) if self.unit == "s" else f"{value / 1e9:.3f} G {self.unit}"

    def line(self) -> str:
        """The figure as one printed line."""
        verdict = "" if self.met is None else ("met" if self.met else "MISSED")
        return (
            f"{self.measure:<13} {self.subject:<20} ours {self.amount(self.ours):>9}  "
            f"{self.reference_name} {self.amount(self.reference):>9}  {self.ratio:6.2f}x  "
            f"{('target ' + self.target) if self.target else '':<16} {verdict} {self.note}".rstrip()
        )

    def as_dict(self) -> dict[str, Any]:
        """For the JSON report."""
        return asdict(self)


def ratio_figure(
    measure: str,
    subject: str,
    ours: float,
    reference_name: str,
    reference: float,
    at_most: float | None = None,
    note: str = "",
    unit: str = "s",
) -> Figure:
    """ours / reference, met when at most ``at_most``."""
    ratio = ours / reference if reference > 0 else float("nan")
    met = None if at_most is None else bool(ratio <= at_most)
    target = "" if at_most is None else f"<= {at_most:g}x"
    return Figure(measure, subject, ours, reference_name, reference, ratio, target, met, note, unit)


def speedup_figure(
    measure: str, subject: str, ours: float, reference_name: str, reference: float, at_least: float
) -> Figure:
    """reference / ours (how many times faster we are), met when at least ``at_least``."""
    ratio = reference / ours if ours > 0 else float("nan")
    return Figure(
        measure,
        subject,
        ours,
        reference_name,
        reference,
        ratio,
        f">= {at_least:g}x faster",
        bool(ratio >= at_least),
        "ratio is a speed-up",
    )
