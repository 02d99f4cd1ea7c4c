"""The scene spec: several assembled robots placed in one model."""

from __future__ import annotations

from typing import Literal

from pydantic import Field

from assembler.spec.part_arguments import DEFAULT
from assembler.spec.schema.common import StrictModel, Vec3
from assembler.spec.schema.parts import Name
from assembler.spec.schema.robot import Arm


class SceneRobot(StrictModel):
    """One robot of a scene, with its parts and its placement."""

    robot: str = Field(min_length=1)
    """A registered robot name, or a robot spec file relative to the scene file."""

    base: Name | None = DEFAULT
    """A registered base name, 'default' for the robot's default base, or null for none."""

    grippers: dict[Arm, Name | None] = Field(default_factory=dict)
    """Gripper per arm: a registered gripper name or null for none; arms left out get their default."""

    pos: Vec3 = (0.0, 0.0, 0.0)
    """Where the robot's bottom goes, in the world frame (metres)."""

    ori: Vec3 = (0.0, 0.0, 0.0)
    """Roll, pitch and yaw (radians), as robosuite's set_base_ori: the rotation Rx(roll) Ry(pitch) Rz(yaw)."""


class SceneSpec(StrictModel):
    """Robots placed together; robot i gets idn i, so every name is unique."""

    kind: Literal["scene"]
    """Marks a scene spec."""

    name: Name
    """The scene's name (the MJCF model name)."""

    description: str = ""
    """One or two sentences about the scene."""

    robots: list[SceneRobot] = Field(min_length=1)
    """The robots, in idn order."""

    floor: bool = True
    """Add a floor plane and a light, so the scene can be simulated and rendered as it is."""
