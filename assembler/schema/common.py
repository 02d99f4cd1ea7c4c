"""Shared building blocks of every spec schema: strict, frozen models and checked number types."""

from __future__ import annotations

from typing import Annotated

from pydantic import BaseModel, ConfigDict, Field

FiniteFloat = Annotated[float, Field(allow_inf_nan=False)]
"""A real number; NaN and infinities are refused at validation."""

NonNegativeFloat = Annotated[float, Field(ge=0.0, allow_inf_nan=False)]
"""A finite number that is zero or larger."""

Vec3 = tuple[FiniteFloat, FiniteFloat, FiniteFloat]
"""Three finite numbers, e.g. a position (x, y, z) in metres."""


Vec4 = tuple[FiniteFloat, FiniteFloat, FiniteFloat, FiniteFloat]
"""Four finite numbers, e.g. a quaternion (w, x, y, z)."""


class StrictModel(BaseModel):
    """Base of all spec models: unknown keys are errors, values are frozen after validation,
    and each field's docstring becomes its description in the JSON Schema."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        use_attribute_docstrings=True,
        validate_default=True,
    )
