"""How a spec changes a part's physical shape and surfaces: body masses and sizes, geom friction.

``bodies:`` entries scale the bodies whose names match: ``size_scale`` S makes a link S times as
large (its geoms and meshes, its sites' positions, its inertial frame and its children's offsets;
a site keeps its size unless it is a touch or contact sensor's zone), with its mass
S^3 and its inertia S^5 times the file's unless ``mass_scale`` gives the mass factor (the inertia
then follows the mass times S^2). ``geoms:`` entries set the friction of the geoms whose names
match. Later entries replace earlier ones' values on the same element, as ``joints:`` entries do.
"""

from __future__ import annotations

from typing import Annotated

from pydantic import Field, model_validator

from assembler.spec.schema.common import NOT_BOOL, NonNegativeFloat, StrictModel, rule_error

PositiveScale = Annotated[float, Field(gt=0.0, allow_inf_nan=False), NOT_BOOL]
"""A finite factor larger than zero."""

BODY_SCALES: tuple[str, ...] = ("mass_scale", "size_scale")
"""The factors a ``bodies:`` entry may set."""


class BodyScale(StrictModel):
    """Scale the mass and size of the bodies whose names match."""

    match: str = Field(min_length=1)
    """A body name as written in the model file (without the robot prefix), or a glob such as 'link[3-5]'."""

    mass_scale: PositiveScale | None = None
    """Factor on the matched bodies' mass (inertia follows it); with size_scale, replaces its S^3."""

    size_scale: PositiveScale | None = None
    """Factor on the matched bodies' geoms, meshes, inertial frame, children's offsets and site
    positions (a site keeps its size, but a touch or contact sensor's zone scales with its geoms);
    mass follows as S^3 and inertia as S^5 unless mass_scale is given."""

    @model_validator(mode="after")
    def _sets_something(self) -> BodyScale:
        if self.mass_scale is None and self.size_scale is None:
            raise rule_error(f"entry for {self.match!r} sets nothing; give mass_scale or size_scale")
        return self

    def values(self) -> dict[str, float]:
        """The factors this entry sets, by name."""
        return {name: value for name in BODY_SCALES if (value := getattr(self, name)) is not None}


class GeomFriction(StrictModel):
    """Set the friction of the geoms whose names match."""

    match: str = Field(min_length=1)
    """A geom name as written in the model file (without the robot prefix), or a glob such as '*_pad'."""

    friction: tuple[NonNegativeFloat, NonNegativeFloat, NonNegativeFloat]
    """Sliding, torsional and rolling friction (MuJoCo's geom friction; its default is 1, 0.005, 0.0001)."""
