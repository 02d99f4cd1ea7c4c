"""Shared building blocks of every spec schema: strict, frozen models and checked number types."""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import AfterValidator, BaseModel, BeforeValidator, ConfigDict, Field
from pydantic_core import PydanticCustomError


def _refuse_bool(value: Any) -> Any:
    if isinstance(value, bool):  # pydantic would read true as 1.0: ``damping: true`` is a mistake
        raise PydanticCustomError(
            "number_type", "expected a number, got {value}", {"value": str(value).lower()}
        )
    return value


NOT_BOOL = BeforeValidator(_refuse_bool)
"""Put in a number type's ``Annotated``: ``true`` and ``false`` are refused, not read as 1 and 0."""

FiniteFloat = Annotated[float, Field(allow_inf_nan=False), NOT_BOOL]
"""A real number; NaN, infinities and booleans are refused at validation."""

NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]*$"

Name = Annotated[str, Field(pattern=NAME_PATTERN, max_length=64)]
"""A registry name: it becomes a Python class name, so letters, digits and underscores."""

NonNegativeFloat = Annotated[float, Field(ge=0.0, allow_inf_nan=False), NOT_BOOL]
"""A finite number that is zero or larger."""


def rule_error(message: str) -> PydanticCustomError:
    """A model validator's error, shown as written (a plain ValueError gets "Value error, " in front)."""
    return PydanticCustomError("spec_rule", message)


def _ordered(value: tuple[float, float]) -> tuple[float, float]:
    low, high = value
    if not low < high:  # MuJoCo refuses such a range only at compile time, far from the spec line
        raise PydanticCustomError(
            "range_order", "expected min < max, got [{low}, {high}]", {"low": low, "high": high}
        )
    return value


Range = Annotated[tuple[FiniteFloat, FiniteFloat], AfterValidator(_ordered)]
"""A (min, max) interval of finite numbers with min < max, e.g. a joint range or a ctrlrange."""

Vec3 = tuple[FiniteFloat, FiniteFloat, FiniteFloat]
"""Three finite numbers, e.g. a position (x, y, z) in metres."""


Vec4 = tuple[FiniteFloat, FiniteFloat, FiniteFloat, FiniteFloat]
"""Four finite numbers, e.g. a quaternion (w, x, y, z)."""


class StrictModel(BaseModel):
    """Base of all spec models: unknown keys are errors, values are frozen after validation,
    and each field's docstring becomes its description in the JSON Schema (given there, by
    :mod:`assembler.spec.schema.json_schema`, not at class creation: see its ``_describe_fields``)."""

    model_config = ConfigDict(
        extra="forbid",
        frozen=True,
        validate_default=True,
        # A model's validator is built when it first validates, not when its module is imported:
        # a process that assembles a robot never pays for the scene and experiment models, nor
        # for a nested model's own validator besides the copy inside the spec that holds it.
        defer_build=True,
    )
