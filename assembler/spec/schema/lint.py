"""What a spec tells ``assembler lint``: findings its authors have judged and accept, each with why."""

from __future__ import annotations

from pydantic import Field

from assembler.spec.schema.common import StrictModel


class Acknowledgement(StrictModel):
    """A lint finding the spec's authors accept: it is still reported, as acknowledged, with the reason."""

    code: str = Field(pattern=r"^RA\d{3}$")
    """The finding's code (e.g. RA601); every finding of this code about this part is acknowledged."""

    reason: str = Field(min_length=10)
    """Why the finding is accepted (e.g. the vendor's own value, kept for parity)."""


class LintOptions(StrictModel):
    """How ``assembler lint`` treats this part's findings."""

    acknowledge: list[Acknowledgement] = Field(default_factory=list)
    """Findings accepted with a reason: reported as acknowledged, and not failing lint; one that
    matches no finding is reported (RA002), to be deleted."""
