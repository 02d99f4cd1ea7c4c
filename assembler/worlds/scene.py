"""Scenes: several robots, each with its base and grippers, placed in one model.

Robot i gets idn i, so its parts are prefixed ``robot{i}_``, ``mobilebase{i}_``, ``gripper{i}_right_``
and never collide. Each robot is placed with ``set_base_xpos`` / ``set_base_ori``. The scene's
``home`` keyframe combines every robot's, base's and grippers' initial pose. Every problem of a
scene file is reported at once, at the entry that causes it.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from assembler.compiler.compile import compile_home
from assembler.errors import AssemblerError, Problem, SpecError
from assembler.files.paths import confine, spec_homes
from assembler.files.regular import not_regular
from assembler.mjcf import census, compose
from assembler.models import RobotModel
from assembler.registry.catalog import register_specs
from assembler.registry.instances import assemble
from assembler.registry.references import placement_reference_problems
from assembler.spec.documents import LocatedDocument, Override, read_validated
from assembler.spec.documents.problems import reading_order
from assembler.spec.fieldpath import FieldPath
from assembler.spec.part_arguments import is_spec_file
from assembler.spec.schema import SceneRobot, SceneSpec

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
        return compile_home(self.mjspec, home, f"scene '{self.spec.name}'")


def robot_reference(reference: str, folder: Path | None = None) -> str:
    """A registered robot name; a robot spec file (relative to ``folder``) is registered first."""
    if is_spec_file(reference, folder or Path.cwd()):
        home = folder or Path.cwd()
        # A scene or experiment from a stranger names robot files as a spec names its parents.
        path = confine(home / reference, spec_homes(home), "robot spec ")
        kind = not_regular(path)
        if kind is not None:  # a folder would register every spec in it
            raise SpecError(f"robot spec {reference}: {kind}; name the robot's spec file")
        (cls,) = register_specs(path)
        return cls.__name__
    return reference


EntryOverrides = Callable[[int, SceneRobot], list[Override]]
"""The overrides of the robot entry at an index (an experiment's; a scene has none)."""


def assemble_entries(
    document: LocatedDocument,
    entries: Sequence[SceneRobot],
    idns: Sequence[int],
    overrides: EntryOverrides | None = None,
    problems: Sequence[Problem] = (),
) -> list[RobotModel]:
    """Assemble each robot entry of a scene or experiment file; every problem at once (with
    ``problems`` found earlier), each at its entry when it has no position of its own."""
    found = list(problems)
    folder = document.folder
    robots: list[RobotModel] = []
    for index, (entry, idn) in enumerate(zip(entries, idns, strict=True)):
        here = FieldPath(("robots", index))
        unknown = placement_reference_problems(document, [entry], index)
        if unknown:
            found += unknown
            continue
        try:
            robots.append(
                assemble(
                    robot_reference(entry.robot, folder),
                    idn=idn,
                    base=entry.base,
                    grippers=dict(entry.grippers.items()),
                    overrides=overrides(index, entry) if overrides is not None else None,
                )
            )
        except AssemblerError as error:
            where = document.where(here)
            found += [p if p.location else Problem(p.message, where, p.path or here) for p in error.problems]
    if found:
        raise SpecError(sorted(found, key=reading_order))
    return robots


def place_robots(spec: SceneSpec, robots: Sequence[RobotModel]) -> Scene:
    """Place assembled robots (one per entry of ``spec``, in order) into one MuJoCo spec, and check
    once that it holds every element of every robot's parts (see :meth:`RobotModel.attach_into`)."""
    assembly = compose.new_assembly(robots[0].source.globals_xml)  # the schema requires a robot
    assembly.modelname = spec.name
    if spec.floor:
        floor = mujoco.MjSpec.from_string(FLOOR_XML)
        compose.attach(assembly, floor, assembly.worldbody.add_frame(), "scene_")
    before, want = census.of_spec(assembly), census.Census()
    for entry, robot in zip(spec.robots, robots, strict=True):
        robot.set_base_xpos(np.array(entry.pos))
        robot.set_base_ori(np.array(entry.ori))
        robot.attach_into(assembly)
        want.update(robot.census_contribution())
    census.require_growth(assembly, before, want, f"building scene '{spec.name}'")
    return Scene(spec=spec, robots=list(robots), mjspec=assembly)


def build_scene(spec: SceneSpec, document: LocatedDocument | None = None) -> Scene:
    """Assemble and place every robot of a scene (robot i gets idn i); problems point into
    ``document`` (the scene file) when there is one."""
    if document is None:
        document = LocatedDocument(spec.model_dump(mode="json"), f"<scene {spec.name}>")
    robots = assemble_entries(document, spec.robots, list(range(len(spec.robots))))
    return place_robots(spec, robots)


def load_scene(path: str | Path) -> Scene:
    """Read, validate and assemble a scene file; robot spec paths are relative to it."""
    loaded = read_validated(path, SceneSpec)
    return build_scene(loaded.spec, loaded.document)
