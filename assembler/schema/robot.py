"""The robot spec: one YAML document that becomes one registered robot class."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, WrapValidator
from pydantic_core import PydanticCustomError

from assembler.schema.base import FiniteFloat, NonNegativeFloat, StrictModel, Vec3
from assembler.schema.expressions import (
    OFFSET_VARIABLES,
    ExpressionError,
    evaluate_expression,
    parse_expression,
)
from assembler.schema.joints import JointDefaults, JointOverride

NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]*$"

Name = Annotated[str, Field(pattern=NAME_PATTERN, max_length=64)]
"""A registry name: it becomes a Python class name, so letters, digits and underscores."""

Morphology = Literal["manipulator", "legged_manipulator", "humanoid", "humanoid_upper_body"]


def _number_or_expression(value: Any, handler: Any) -> Any:
    """Accept a finite number, or an expression text that our own grammar can parse."""
    if isinstance(value, str):
        try:
            parse_expression(value)
        except ExpressionError as error:
            raise PydanticCustomError("offset_expression", str(error)) from None
        return value
    try:
        return handler(value)
    except Exception as error:  # pydantic's ValidationError, re-raised as one readable line
        raise PydanticCustomError(
            "offset_value",
            "expected a number or an expression such as '-0.16 - table_length / 2', got {value}",
            {"value": repr(value)},
        ) from error


OffsetValue = Annotated[FiniteFloat | str, WrapValidator(_number_or_expression)]
"""A number, or an expression over """ + ", ".join(OFFSET_VARIABLES) + " (no Python is evaluated)."

Offset3 = tuple[OffsetValue, OffsetValue, OffsetValue]


class RobotSpec(StrictModel):
    """A robot: its MJCF, morphology, joint parameters, initial pose and placement offsets."""

    kind: Literal["robot"] = "robot"
    """What this document describes; robot specs may leave it out."""

    name: Name
    """The registry name, e.g. 'Sparrow7'; `create_robot(name)` and `assembler build <name>` use it."""

    extends: str | None = None
    """A registered robot name or a spec file (relative to this file) whose fields this spec inherits."""

    description: str = ""
    """One or two sentences for `assembler list` and the generated docs."""

    mjcf: str = Field(min_length=1)
    """The robot's MJCF file: relative to this spec file, absolute, or 'package://<python package>/<path>'."""

    morphology: Morphology = "manipulator"
    """The model class the spec becomes: a manipulator, legged manipulator, or (upper-body) humanoid."""

    default_base: Name | None = None
    """The base the robot is assembled with by default (a registered base name), or null for none."""

    default_controller_config: dict[str, str] = Field(default_factory=dict)
    """Controller config name per body part (e.g. right: default_panda), for controller libraries."""

    init_qpos: list[FiniteFloat] | None = None
    """Initial joint positions, one per robot joint in MuJoCo's order; null keeps the MJCF's qpos0."""

    base_xpos_offset: dict[str, Offset3] = Field(default_factory=dict)
    """Placement of the robot's base per arena (e.g. bins, empty, table); entries may use table_length."""

    top_offset: Vec3 = (0.0, 0.0, 1.0)
    """Offset from the robot's root to its top, in metres (robosuite's placeholder is 0, 0, 1)."""

    horizontal_radius: NonNegativeFloat = 0.5
    """Radius of the robot's footprint in metres, for placing it clear of other objects."""

    joint_defaults: JointDefaults = Field(default_factory=JointDefaults)
    """Rules for frictionloss, damping and armature where the MJCF sets none."""

    joints: list[JointOverride] = Field(default_factory=list)
    """Per-joint overrides, applied in order after the default rules."""

    def resolve_base_xpos_offset(self, arena: str, **variables: float) -> tuple[float, float, float]:
        """The base offset for ``arena`` with expression variables bound (e.g. ``table_length=0.8``)."""
        if arena not in self.base_xpos_offset:
            known = ", ".join(self.base_xpos_offset) or "(none)"
            raise KeyError(f"robot {self.name!r} has no base_xpos_offset for {arena!r}; known: {known}")
        x, y, z = (evaluate_expression(v, variables) for v in self.base_xpos_offset[arena])
        return (x, y, z)
