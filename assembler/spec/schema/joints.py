"""How a spec sets joint parameters: default rules over all of the robot's joints, and overrides.

robosuite applies three rules to every robot joint that its MJCF leaves unset: frictionloss 0.1,
damping 0.1 and armature 5.0/(i+1), i being the joint's index. A spec can replace each rule with a
scalar, a per-joint list, the inverse-index rule with another scale, or ``null`` (no rule).
"""

from __future__ import annotations

from typing import Annotated, Any

from pydantic import Field, WrapValidator, model_validator
from pydantic_core import PydanticCustomError

from assembler.spec.schema.common import NOT_BOOL, NonNegativeFloat, StrictModel

JOINT_RULE_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature")
"""The joint attributes that have a default rule, in the order robosuite applies them."""

OVERRIDABLE_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")
"""The joint attributes a per-joint override may set."""


class InverseIndexRule(StrictModel):
    """Value ``inverse_index / (i + 1)`` for the robot's i-th joint (0-based, MuJoCo's joint order)."""

    inverse_index: Annotated[float, Field(gt=0.0, allow_inf_nan=False), NOT_BOOL]
    """The scale: robosuite uses 5.0 for armature, giving 5.0, 2.5, 1.667, ..."""


def _shown(value: Any) -> str:
    """A value as YAML writes it where it matters (``true``, ``[true, 0.1]``), else as Python does."""
    if isinstance(value, bool):
        return str(value).lower()
    if isinstance(value, list):
        return "[" + ", ".join(_shown(item) for item in value) + "]"
    return repr(value)


def _one_message_for_rule(value: Any, handler: Any) -> Any:
    """Validate a rule, turning pydantic's one-error-per-union-member into one clear message."""
    if value is None:
        return None
    try:
        return handler(value)
    except Exception as error:  # pydantic's ValidationError; re-raised as one readable line
        raise PydanticCustomError(
            "joint_rule",
            "expected a non-negative number, a list of them (one per joint), "
            "a mapping 'inverse_index: <scale>' or null, got {value}",
            {"value": _shown(value)},
        ) from error


JointRule = Annotated[
    NonNegativeFloat | list[NonNegativeFloat] | InverseIndexRule | None,
    WrapValidator(_one_message_for_rule),
]
"""A default rule: one value for all joints, one value per joint, the inverse-index rule, or none."""


class JointDefaults(StrictModel):
    """Default rules applied where the MJCF sets nothing (MuJoCo's own default resolution decides)."""

    frictionloss: JointRule = 0.1
    """Dry friction (N m or N) for every joint the MJCF leaves unset; robosuite uses 0.1."""

    damping: JointRule = 0.1
    """Viscous damping for every joint the MJCF leaves unset; robosuite uses 0.1."""

    armature: JointRule = InverseIndexRule(inverse_index=5.0)
    """Rotor inertia added to each joint the MJCF leaves unset; robosuite uses 5.0/(i+1)."""


class JointOverride(StrictModel):
    """Set parameters of the joints whose names match, after the default rules."""

    match: str = Field(min_length=1)
    """A joint name as written in the MJCF (without the robot prefix), or a glob such as 'joint[67]'."""

    frictionloss: NonNegativeFloat | None = None
    """Dry friction for the matched joints."""

    damping: NonNegativeFloat | None = None
    """Viscous damping for the matched joints."""

    armature: NonNegativeFloat | None = None
    """Rotor inertia for the matched joints."""

    stiffness: NonNegativeFloat | None = None
    """Spring stiffness towards the joint's springref for the matched joints."""

    force: bool = True
    """If false, values the MJCF itself sets are kept and only rule-given values are replaced."""

    @model_validator(mode="after")
    def _sets_something(self) -> JointOverride:
        if all(getattr(self, name) is None for name in OVERRIDABLE_ATTRIBUTES):
            raise ValueError(
                f"override for {self.match!r} sets nothing; give one of " + ", ".join(OVERRIDABLE_ATTRIBUTES)
            )
        return self

    def values(self) -> dict[str, float]:
        """The attributes this override sets, by name."""
        return {name: value for name in OVERRIDABLE_ATTRIBUTES if (value := getattr(self, name)) is not None}
