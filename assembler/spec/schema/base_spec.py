"""The base spec: what a robot stands on, and how the assembler merges it with the robot."""

from __future__ import annotations

from typing import Any, Literal

from pydantic import Field, field_validator

from assembler.spec.schema.added_joints import AddedJoints
from assembler.spec.schema.common import NonNegativeFloat, Vec3
from assembler.spec.schema.parts import PartSpec

BaseType = Literal["mount", "mobile", "legged", "null"]


class BaseSpec(PartSpec):
    """A fixed mount, a wheeled mobile base, a legged base, or a null base (sites only)."""

    kind: Literal["base"]
    """Marks a base spec."""

    type: BaseType
    """How it merges: mount (under the robot's root), mobile or legged (arm on `support_body`), null."""

    @field_validator("type", mode="before")
    @classmethod
    def _yaml_null_means_null_base(cls, value: Any) -> Any:
        # `type: null` in YAML is the null value, not the text; both mean a null base.
        return "null" if value is None else value

    support_body: str = "support"
    """The body the robot's arm is attached to (mobile and legged bases), as named in the MJCF."""

    top_offset: Vec3 = (0.0, 0.0, 0.0)
    """Offset from the base's root to the surface the robot stands on (metres)."""

    bottom_offset: Vec3 | None = None
    """Offset from the base's root to its bottom; null: the root body's MJCF position (robosuite)."""

    horizontal_radius: NonNegativeFloat = 0.0
    """Radius of the base's footprint in metres."""

    joint_groups: dict[Literal["base", "torso", "legs", "head"], list[str]] | None = None
    """Body-part membership of the base's joints (names or globs); null uses robosuite's name rules."""

    remove_actuation: list[str] = Field(default_factory=list)
    """Joints (names or globs) removed with everything that drives or measures them."""

    remove_free_joint: bool = False
    """Remove the base's free joint (a floating legged base becomes welded)."""

    add_free_joint: bool = False
    """Give the base's root body a free joint (a URDF cannot declare one): a legged base then moves its
    robot's root with it, standing on its own feet. The root body must have no joint of its own."""

    added_joints: AddedJoints = Field(default_factory=list)
    """Joints added after the removals, e.g. planar mobile joints that make a legged base floating."""
