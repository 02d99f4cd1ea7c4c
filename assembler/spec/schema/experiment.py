"""The experiment spec: the robots of one experiment, each with its parts, placement and overrides.

An experiment file is a scene whose robots may change spec fields (Hydra-style dotted keys), so
an experiment's whole robot configuration is one reviewed YAML file.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field

from assembler.spec.schema.common import NOT_BOOL, StrictModel
from assembler.spec.schema.parts import Name
from assembler.spec.schema.scene import SceneRobot, SceneSpec


class ExperimentRobot(SceneRobot):
    """One robot of an experiment: a scene robot that may override fields of its spec."""

    overrides: dict[str, Any] = Field(default_factory=dict)
    """Spec fields to change, by dotted path: {joint_defaults.damping: 0.2, init_qpos[3]: -2.0}."""

    idn: Annotated[int, Field(ge=0), NOT_BOOL] | None = None
    """Instance number (names get the prefix robot{idn}_); null: the robot's position in the list."""


class ExperimentSpec(StrictModel):
    """The robots of one experiment; one robot is built alone, several are placed in one scene."""

    kind: Literal["experiment"]
    """Marks an experiment spec."""

    name: Name
    """The experiment's name (the MJCF model name when it has several robots)."""

    description: str = ""
    """One or two sentences about the experiment."""

    robots: list[ExperimentRobot] = Field(min_length=1)
    """The robots, each by registered name or robot spec file (relative to this file)."""

    floor: bool = True
    """With several robots: add a floor plane and a light, as a scene does."""

    def as_scene(self) -> SceneSpec:
        """The placement part of the experiment (robots, bases, grippers, poses) as a scene spec."""
        placement = set(SceneRobot.model_fields)
        return SceneSpec(
            kind="scene",
            name=self.name,
            description=self.description,
            robots=[SceneRobot.model_validate(r.model_dump(include=placement)) for r in self.robots],
            floor=self.floor,
        )
