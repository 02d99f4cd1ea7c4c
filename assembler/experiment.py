"""Experiment files: the robots of one experiment (with overrides, bases, grippers, placement).

``load_experiment(path)`` assembles every robot; with several, they are placed in one
:class:`~assembler.scene.Scene` by the scene builder. Problems point at the experiment file's
line and column: an unknown robot at its entry, a bad override at its key.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np
from pydantic import ValidationError

from assembler.assembly import assemble
from assembler.errors import AssemblerError, Problem, SpecError
from assembler.loader import problems_from_validation
from assembler.mjcf.emit import to_xml
from assembler.models import RobotModel
from assembler.overrides import Override, parse_path
from assembler.paths import display_path
from assembler.scene import Scene, place_robots, robot_reference
from assembler.schema import ExperimentRobot, ExperimentSpec
from assembler.yaml_source import LocatedDocument, parse_yaml, read_yaml_text


@dataclass
class Experiment:
    """An experiment's assembled robots, and their scene when there are several."""

    spec: ExperimentSpec
    robots: list[RobotModel]
    scene: Scene | None

    @property
    def mjspec(self) -> mujoco.MjSpec:
        """The scene's MuJoCo spec, or the one robot's assembly."""
        return self.scene.mjspec if self.scene is not None else self.robots[0].mjspec

    def get_model(self) -> mujoco.MjModel:
        """Compile the experiment (with one ``home`` keyframe for every robot)."""
        return self.scene.get_model() if self.scene is not None else self.robots[0].get_model()

    def get_xml(self) -> str:
        """The experiment as one standalone MJCF document (compiled first, so it is valid)."""
        self.get_model()
        return to_xml(self.mjspec)


def read_experiment(path: str | Path) -> tuple[ExperimentSpec, LocatedDocument]:
    """Read and validate an experiment file, with file:line:col on every problem."""
    file = Path(path)
    document = parse_yaml(read_yaml_text(file, display_path(file)), display_path(file))
    try:
        return ExperimentSpec.model_validate(document.data), document
    except ValidationError as error:
        raise SpecError(problems_from_validation(error, document, ExperimentSpec)) from None


def _overrides(entry: ExperimentRobot, index: int, document: LocatedDocument) -> list[Override]:
    label = f"robots[{index}].overrides."
    found: list[Override] = []
    for key, value in entry.overrides.items():
        where = document.location(("robots", index, "overrides", key))
        found.append(Override(parse_path(key, label, where), value, label, where))
    return found


def _assemble(entry: ExperimentRobot, index: int, document: LocatedDocument, folder: Path) -> RobotModel:
    """One robot of the experiment; problems without a position of their own get the entry's."""
    try:
        return assemble(
            robot_reference(entry.robot, folder),
            idn=index if entry.idn is None else entry.idn,
            base=entry.base,
            grippers=dict(entry.grippers.items()),
            overrides=_overrides(entry, index, document),
        )
    except AssemblerError as error:
        where = document.location(("robots", index))
        raise type(error)(
            [
                p if p.location else Problem(p.message, where, p.path or f"robots[{index}]")
                for p in error.problems
            ]
        ) from None


def build_experiment(spec: ExperimentSpec, document: LocatedDocument, folder: Path) -> Experiment:
    """Assemble every robot of ``spec`` (all problems at once); place them when there are several."""
    robots: list[RobotModel] = []
    problems: list[Problem] = []
    seen: dict[int, int] = {}  # idn -> first robot index
    for index, entry in enumerate(spec.robots):
        idn = index if entry.idn is None else entry.idn
        if idn in seen:
            where = document.location(("robots", index, "idn"))
            problems.append(
                Problem(
                    f"idn {idn} is already used by robots[{seen[idn]}]; give each robot its own",
                    where,
                    f"robots[{index}].idn",
                )
            )
            continue
        seen[idn] = index
        try:
            robots.append(_assemble(entry, index, document, folder))
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise SpecError(problems)
    if len(robots) > 1:
        return Experiment(spec=spec, robots=robots, scene=place_robots(spec.as_scene(), robots))
    # One robot is built alone, as `assembler build` would, and moved only where the file says.
    (entry,) = spec.robots
    if "pos" in entry.model_fields_set:
        robots[0].set_base_xpos(np.array(entry.pos))
    if "ori" in entry.model_fields_set:
        robots[0].set_base_ori(np.array(entry.ori))
    return Experiment(spec=spec, robots=robots, scene=None)


def load_experiment(path: str | Path) -> Experiment:
    """Read, validate and assemble an experiment file; robot spec paths are relative to it."""
    spec, document = read_experiment(path)
    return build_experiment(spec, document, Path(path).parent)
