"""Joints a base spec adds to its MJCF, each optionally driven by a velocity actuator: how a legged
base becomes a floating one moved by planar mobile joints (robosuite's SpotFloating)."""

from __future__ import annotations

from typing import Literal

from assembler.spec.schema.common import NonNegativeFloat, Range, StrictModel, Vec3
from assembler.spec.schema.parts import Name


class VelocityActuator(StrictModel):
    """A velocity servo on an added joint."""

    name: Name
    """The actuator's name, as in an MJCF file (the part's prefix is added)."""

    kv: NonNegativeFloat
    """Velocity gain."""

    ctrlrange: Range
    """Range of the commanded velocity (m/s or rad/s)."""

    forcerange: Range | None = None
    """Range of the actuator force; null leaves it unlimited."""


class AddedJoint(StrictModel):
    """One joint added to a body of the part's MJCF."""

    name: Name
    """The joint's name, as in an MJCF file (the part's prefix is added)."""

    type: Literal["slide", "hinge"]
    """Slide (translation along axis) or hinge (rotation about axis)."""

    axis: Vec3
    """The joint axis in the body's frame."""

    pos: Vec3 = (0.0, 0.0, 0.0)
    """The joint's position in the body's frame (metres)."""

    body: str | None = None
    """The body it is added to, as named in the MJCF; null: the root body."""

    damping: NonNegativeFloat = 0.0
    """Joint damping."""

    armature: NonNegativeFloat = 0.0
    """Rotor inertia added to the joint."""

    frictionloss: NonNegativeFloat = 0.0
    """Dry friction of the joint."""

    range: Range | None = None
    """Joint limits; null leaves the joint unlimited."""

    actuator: VelocityActuator | None = None
    """A velocity actuator driving this joint, or null."""


AddedJoints = list[AddedJoint]
"""Added joints, in order: they follow the body's own joints in MuJoCo's joint order."""
