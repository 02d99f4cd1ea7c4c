"""What an mjlab task needs of a robot (``assembler.mjlab.entity_cfg``): a robot spec's ``mjlab:`` block.

mjlab's tasks read an IMU (sensors ``imu_ang_vel``, ``imu_lin_vel``, ``root_angmom``), the feet (a site
on each, a contact sensor over them), a soft joint-limit factor and a spawn pose; every field has a
default, so a spec without the block still gives an entity (the IMU at the root, the spec's `feet`).
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field

from assembler.spec.schema.common import NOT_BOOL, StrictModel, Vec3

Fraction = Annotated[float, Field(gt=0.0, le=1.0, allow_inf_nan=False), NOT_BOOL]
"""A number in (0, 1]."""

JointRules = Literal["spec", "robosuite"]
"""Which joint default rules an mjlab entity gets: only those the spec writes, or robosuite's too."""


class MjlabOptions(StrictModel):
    """What mjlab's tasks read of the robot beyond its model; every field has a default."""

    imu_body: str | None = None
    """The body carrying the IMU site (as named in the MJCF); null: the root body."""

    imu_pos: Vec3 = (0.0, 0.0, 0.0)
    """The IMU site's position in that body's frame (metres)."""

    feet: list[str] = Field(default_factory=list)
    """The bodies the robot stands on (as named in the MJCF), each given a site at its lowest point and
    watched by the feet contact sensor; empty: the spec's `feet`."""

    foot_friction: Annotated[float, Field(gt=0.0, allow_inf_nan=False), NOT_BOOL] | None = None
    """Sliding friction of the feet's collision geoms in mjlab (they then win contacts with priority 1);
    null keeps the MJCF's."""

    foot_condim: Literal[1, 3, 4, 6] | None = None
    """Contact dimensionality of the feet's collision geoms in mjlab; null keeps the MJCF's."""

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
