"""Experiment files: the robots of one experiment (with overrides, bases, grippers, placement).

``load_experiment(path)`` assembles every robot; with several, they are placed in one
:class:`~assembler.worlds.scene.Scene` by the scene builder. Problems point at the experiment file's
line and column: an unknown robot at its entry, a bad override at its key.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco
import numpy as np

from assembler.errors import Problem
from assembler.mjcf.emit import to_xml
from assembler.models import RobotModel
from assembler.spec.documents import LoadedSpec, Override, parse_path, read_validated
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import ExperimentRobot, ExperimentSpec, SceneRobot
from assembler.worlds.scene import Scene, assemble_entries, place_robots


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
        """The experiment as one standalone MJCF document (compiled first, so it is valid); one robot's
        is the text ``assembler build`` writes for it with the same overrides."""
        if self.scene is None:
            return self.robots[0].get_xml()
        self.get_model()
        return to_xml(self.mjspec)


def read_experiment(path: str | Path) -> LoadedSpec[ExperimentSpec]:
    """Read and validate an experiment file, with file:line:col on every problem."""
    return read_validated(path, ExperimentSpec)


def _idns(loaded: LoadedSpec[ExperimentSpec]) -> tuple[list[int], list[Problem]]:
    """Each robot's idn (its index unless given); one idn used twice is a problem at the second."""
    idns: list[int] = []
    problems: list[Problem] = []
    seen: dict[int, int] = {}
    for index, entry in enumerate(loaded.spec.robots):
        idn = index if entry.idn is None else entry.idn
        if idn in seen:
            message = f"idn {idn} is already used by robots[{seen[idn]}]; give each robot its own"
            problems.append(loaded.problem(FieldPath(("robots", index, "idn")), message))
        seen.setdefault(idn, index)
        idns.append(idn)
    return idns, problems


def build_experiment(loaded: LoadedSpec[ExperimentSpec]) -> Experiment:
    """Assemble every robot of an experiment (all problems at once); place them when there are several."""
    spec, document = loaded.spec, loaded.document

    def overrides(index: int, entry: SceneRobot) -> list[Override]:
        assert isinstance(entry, ExperimentRobot)
        label = f"robots[{index}].overrides."
        found: list[Override] = []
        for key, value in entry.overrides.items():
            where = document.field_location(FieldPath(("robots", index, "overrides", key)))
            found.append(Override(parse_path(key, label, where), value, label, where))
        return found

    idns, idn_problems = _idns(loaded)
    robots = assemble_entries(document, spec.robots, idns, overrides, idn_problems)
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
    return build_experiment(read_experiment(path))
