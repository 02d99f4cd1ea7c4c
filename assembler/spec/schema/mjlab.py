"""What an mjlab task needs of a robot (``assembler.mjlab.entity_cfg``): a robot spec's ``mjlab:`` block.

mjlab's tasks read an IMU (sensors ``imu_ang_vel``, ``imu_lin_vel``, ``root_angmom``), the feet (a site
on each, a contact sensor over them), a soft joint-limit factor and a spawn pose, and its robots declare
which geoms collide and how (``collisions``, mjlab's ``CollisionCfg``); every field has a default, so a
spec without the block still gives an entity (the IMU at the root, the spec's `feet`, the MJCF's contacts).
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Annotated, Literal

from pydantic import AfterValidator, Field, model_validator
from pydantic_core import PydanticCustomError

from assembler.spec.schema.common import (
    NOT_BOOL,
    FiniteFloat,
    NonNegativeFloat,
    StrictModel,
    Vec3,
    rule_error,
)

Fraction = Annotated[float, Field(gt=0.0, le=1.0, allow_inf_nan=False), NOT_BOOL]
"""A number in (0, 1]."""

JointRules = Literal["spec", "robosuite"]
"""Which joint default rules an mjlab entity gets: only those the spec writes, or robosuite's too."""


Condim = Literal[1, 3, 4, 6]
"""MuJoCo's contact dimensionality: 1 frictionless, 3 sliding friction, 4 also torsional, 6 also rolling."""

Bitmask = Annotated[int, Field(ge=0), NOT_BOOL]
"""A non-negative integer read bit by bit (MuJoCo's contype and conaffinity)."""


def _compiles(pattern: str) -> str:
    try:
        re.compile(pattern)
    except re.error as error:  # refused here, at the spec's line, not when mjlab builds the entity
        raise PydanticCustomError(
            "regex",
            "'{pattern}' is not a regular expression: {reason}",
            {"pattern": pattern, "reason": str(error)},
        ) from None
    return pattern


GeomPattern = Annotated[str, Field(min_length=1), AfterValidator(_compiles)]
"""A regular expression over geom names (Python's ``re``), matched against the whole name."""


def _solref(value: tuple[float, float]) -> tuple[float, float]:
    if (value[0] > 0) != (value[1] > 0):  # MuJoCo replaces a mixed solref by its default, with a warning
        raise PydanticCustomError(
            "solref",
            "expected two positive numbers (time constant, damping ratio) or two that are not "
            "(-stiffness, -damping), got {value}",
            {"value": list(value)},
        )
    return value


SOLIMP_RULES: tuple[tuple[str, str, Callable[[float], bool]], ...] = (
    ("dmin", "in (0, 1)", lambda v: 0 < v < 1),
    ("dmax", "in (0, 1)", lambda v: 0 < v < 1),
    ("width", ">= 0", lambda v: v >= 0),
    ("midpoint", "in (0, 1)", lambda v: 0 < v < 1),
    ("power", ">= 1", lambda v: v >= 1),
)
"""solimp's values in order, with the range MuJoCo clamps each into without a word."""


def _solimp(value: tuple[float, ...]) -> tuple[float, ...]:
    for (name, rule, holds), number in zip(SOLIMP_RULES, value, strict=False):
        if not holds(number):
            raise PydanticCustomError(
                "solimp",
                "{name} must be {rule}, got {number}",
                {"name": name, "rule": rule, "number": number},
            )
    return value


class MjlabCollision(StrictModel):
    """Contact settings mjlab gives the robot's geoms whose names match (one mjlab ``CollisionCfg``): each
    field left out keeps what the geom has before this entry (the MJCF's, or an earlier entry's)."""

    geoms: list[GeomPattern] = Field(min_length=1)
    """Regular expressions over geom names as the MJCF writes them (without the robot prefix), each matched
    against the whole name ('.*_collision.*', 'left_foot[1-7]_collision'; mjlab itself matches from
    the start only); a geom without a name is '<body>_geom<i>', its body's name and its place among that
    body's geoms. Each must match at least one geom."""

    contype: Bitmask | None = None
    """Collision type bitmask: two geoms collide when one's contype shares a bit with the other's
    conaffinity (mjlab's terrain: contype 1, conaffinity 1); 0 with conaffinity 0 turns the geoms off."""

    conaffinity: Bitmask | None = None
    """Collision affinity bitmask (see contype); mjlab's feet-only setting gives the feet contype 0 and
    conaffinity 1, so they touch the terrain and not each other."""

    condim: Condim | None = None
    """Contact dimensionality: 1 frictionless, 3 sliding friction, 4 also torsional, 6 also rolling."""

    priority: Annotated[int, Field(ge=0), NOT_BOOL] | None = None
    """Contact priority: in a contact, the geom of higher priority gives its condim, friction, solref and
    solimp (mjlab's feet: 1, every other geom 0)."""

    friction: Annotated[tuple[NonNegativeFloat, ...], Field(min_length=1, max_length=3)] | None = None
    """Friction coefficients, written from the first: sliding (unitless), torsional (m), rolling (m); those
    not given keep their value (mjlab's G1 feet: [0.6])."""

    solref: Annotated[tuple[FiniteFloat, FiniteFloat], AfterValidator(_solref)] | None = None
    """Contact softness: [time constant (s), damping ratio], both positive, or [-stiffness (N/m),
    -damping (N s/m)], neither positive (mjlab's Go1: [0.01, 1])."""

    solimp: (
        Annotated[tuple[FiniteFloat, ...], Field(min_length=3, max_length=5), AfterValidator(_solimp)] | None
    ) = None
    """Contact impedance, written from the first: dmin and dmax in (0, 1), width (m) >= 0, then midpoint
    in (0, 1) and power >= 1 if given; those not given keep their value (mjlab's Go1 feet:
    [0.9, 0.95, 0.023])."""

    margin: NonNegativeFloat | None = None
    """Distance (m) within which contacts are detected."""

    gap: NonNegativeFloat | None = None
    """Part of the margin (m) in which detected contacts do not push: they count when their distance is
    below margin - gap."""

    solmix: Annotated[float, Field(ge=0.0, le=1.0, allow_inf_nan=False), NOT_BOOL] | None = None
    """Weight of this geom's solref and solimp against the other geom's in a contact of equal priority."""

    @model_validator(mode="after")
    def _sets_something(self) -> MjlabCollision:
        settings = [name for name in MjlabCollision.model_fields if name != "geoms"]
        if all(getattr(self, name) is None for name in settings):
            raise rule_error(f"the entry for {self.geoms} sets nothing; give one of {', '.join(settings)}")
        return self


class MjlabOptions(StrictModel):
    """What mjlab's tasks read of the robot beyond its model; every field has a default."""

    imu_body: str | None = None
    """The body carrying the IMU site (as named in the MJCF); null: the root body."""

    imu_pos: Vec3 = (0.0, 0.0, 0.0)
    """The IMU site's position in that body's frame (metres)."""

    feet: list[str] = Field(default_factory=list)
    """The bodies the robot stands on (as named in the MJCF), each given a site at its lowest point and
    watched by the feet contact sensor; empty: the spec's `feet`."""

    collisions: list[MjlabCollision] = Field(default_factory=list)
    """Contact settings by geom name (mjlab's ``CollisionCfg``), applied in order, a later entry winning
    where two match a geom; geoms no entry matches keep the MJCF's. foot_friction and foot_condim are
    applied after them, to the feet's collision geoms."""

    foot_friction: Annotated[float, Field(gt=0.0, allow_inf_nan=False), NOT_BOOL] | None = None
    """Sliding friction of the feet's collision geoms in mjlab (they then win contacts with priority 1),
    applied after `collisions`; null keeps the MJCF's (or what `collisions` set)."""

    foot_condim: Condim | None = None
    """Contact dimensionality of the feet's collision geoms in mjlab (they then win contacts with
    priority 1), applied after `collisions`; null keeps the MJCF's (or what `collisions` set)."""

    soft_joint_pos_limit_factor: Fraction = 1.0
    """The fraction of each joint's range mjlab's limit terms treat as allowed (mjlab's Go1 and G1: 0.9)."""

    floating: bool | None = None
    """Whether the robot's root floats in mjlab: true gives it a free joint even where the spec welds it
    (a walking task), false welds it; null: as the spec has it."""

    spawn_pos: Vec3 | None = None
    """Where mjlab puts the root (metres, in its environment's frame); null: a floating robot stands on the
    floor at its home pose (its lowest collision point at z = 0), a welded one where its home pose puts it."""

    joint_rules: JointRules = "spec"
    """spec: the entity gets the joint default rules the spec writes (`joint_defaults`), none otherwise;
    robosuite: also robosuite's rules (armature 5/(i+1), damping, frictionloss 0.1) where it writes none."""
