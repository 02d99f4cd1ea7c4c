"""Scenes: several robots, each with its base and grippers, placed in one model.

Robot i gets idn i, so its parts are prefixed ``robot{i}_``, ``mobilebase{i}_``, ``gripper{i}_right_``
and never collide. Each robot is placed with ``set_base_xpos`` / ``set_base_ori``. The scene's
``home`` keyframe combines every robot's, base's and gripper's initial pose.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np
from pydantic import ValidationError

from assembler.assembly import assemble
from assembler.catalog import register_specs
from assembler.errors import SpecError
from assembler.loader import SPEC_SUFFIXES, problems_from_validation
from assembler.mjcf import compose
from assembler.mjcf.keyframe import compile_with_home
from assembler.models import RobotModel
from assembler.paths import confine, display_path
from assembler.schema import SceneSpec
from assembler.yaml_source import parse_yaml, read_yaml_text

FLOOR_XML = """<mujoco>
  <asset>
    <texture name="grid" type="2d" builtin="checker" rgb1=".75 .75 .75" rgb2=".6 .6 .6"
             width="256" height="256"/>
    <material name="grid" texture="grid" texrepeat="8 8" reflectance="0.1"/>
  </asset>
  <worldbody>
    <light name="light" pos="0 0 4" dir="0 0 -1" directional="true"/>
    <geom name="floor" type="plane" size="0 0 0.05" material="grid"/>
  </worldbody>
</mujoco>"""


@dataclass
class Scene:
    """The assembled robots and the scene's MuJoCo spec."""

    spec: SceneSpec
    robots: list[RobotModel]
    mjspec: mujoco.MjSpec

    def get_model(self) -> mujoco.MjModel:
        """Compile the scene with one ``home`` keyframe for every robot."""
        home: dict[str, float] = {}
        for robot in self.robots:
            home.update(robot.assembly_home())
        return compile_with_home(self.mjspec, home, f"scene '{self.spec.name}'")


def load_scene_spec(path: str | Path) -> SceneSpec:
    """Read and validate a scene file, with file:line:col on every problem."""
    file = Path(path)
    document = parse_yaml(read_yaml_text(file, display_path(file)), display_path(file))
    try:
        return SceneSpec.model_validate(document.data)
    except ValidationError as error:
        raise SpecError(problems_from_validation(error, document, SceneSpec)) from None


def robot_reference(reference: str, folder: Path | None = None) -> str:
    """A registered robot name; a robot spec file (relative to ``folder``) is registered first."""
    if reference.endswith(SPEC_SUFFIXES):
        home = folder or Path.cwd()
        # A scene or experiment from a stranger names robot files as a spec names its parents.
        (cls,) = register_specs(confine(home / reference, [home], "robot spec "))
        return cls.__name__
    return reference


def place_robots(spec: SceneSpec, robots: Sequence[RobotModel]) -> Scene:
    """Place assembled robots (one per entry of ``spec``, in order) into one MuJoCo spec."""
    assembly: mujoco.MjSpec | None = None
    for entry, robot in zip(spec.robots, robots, strict=True):
        robot.set_base_xpos(np.array(entry.pos))
        robot.set_base_ori(np.array(entry.ori))
        if assembly is None:
            assembly = compose.new_assembly(robot.source.globals_xml)
            assembly.modelname = spec.name
            if spec.floor:
                floor = mujoco.MjSpec.from_string(FLOOR_XML)
                compose.attach(assembly, floor, assembly.worldbody.add_frame(), "scene_")
        robot.build_into(assembly)
    assert assembly is not None  # the schema requires at least one robot
    return Scene(spec=spec, robots=list(robots), mjspec=assembly)


def build_scene(spec: SceneSpec, folder: Path | None = None) -> Scene:
    """Assemble and place every robot of ``spec`` into one MuJoCo spec."""
    robots = [
        assemble(robot_reference(e.robot, folder), idn=idn, base=e.base, grippers=dict(e.grippers.items()))
        for idn, e in enumerate(spec.robots)
    ]
    return place_robots(spec, robots)


def load_scene(path: str | Path) -> Scene:
    """Read, validate and assemble a scene file; robot spec paths are relative to it."""
    file = Path(path)
    return build_scene(load_scene_spec(file), file.parent)
