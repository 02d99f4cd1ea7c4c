"""Names a spec gives that must be registered: a robot's default base and grippers, the robots,
bases and grippers of a scene or experiment. Each miss is one problem at the field that names it,
with the closest registered name; names inside the MJCF are checked by the parts themselves
(:mod:`assembler.models.spec_names`).
"""

from __future__ import annotations

from collections.abc import Sequence

from assembler.errors import Problem, RegistryError
from assembler.models import REGISTRIES
from assembler.spec.documents import LoadedSpec, LocatedDocument
from assembler.spec.fieldpath import FieldPath
from assembler.spec.part_arguments import DEFAULT, is_spec_file
from assembler.spec.schema import PartSpec, RobotSpec, SceneRobot


def registry_problem(document: LocatedDocument, path: FieldPath, family: str, name: str) -> list[Problem]:
    """A problem at ``path`` when ``name`` is not a registered ``family`` (robot, base, gripper)."""
    try:
        REGISTRIES[family].lookup(name)
    except RegistryError as error:
        return [document.problem(path, p.message) for p in error.problems]
    return []


def spec_reference_problems(loaded: LoadedSpec[PartSpec]) -> list[Problem]:
    """A robot spec's default base and grippers must be registered."""
    spec, document = loaded.spec, loaded.document
    if not isinstance(spec, RobotSpec):
        return []
    problems: list[Problem] = []
    if spec.default_base is not None:
        problems += registry_problem(document, FieldPath(("default_base",)), "base", spec.default_base)
    for arm, gripper in spec.default_grippers.items():
        if gripper is not None:
            problems += registry_problem(document, FieldPath(("default_grippers", arm)), "gripper", gripper)
    return problems


def placement_reference_problems(
    document: LocatedDocument, robots: Sequence[SceneRobot], first_index: int = 0
) -> list[Problem]:
    """Each robot of a scene or experiment (``robots[first_index]`` onwards): a registered robot (or a
    spec file), base and grippers."""
    problems: list[Problem] = []
    for index, entry in enumerate(robots, start=first_index):
        here = FieldPath(("robots", index))
        if not is_spec_file(entry.robot, document.folder):
            problems += registry_problem(document, here.child("robot"), "robot", entry.robot)
        if entry.base not in (None, DEFAULT):
            problems += registry_problem(document, here.child("base"), "base", str(entry.base))
        for arm, gripper in entry.grippers.items():
            if gripper is not None:
                problems += registry_problem(document, here.child("grippers").child(arm), "gripper", gripper)
    return problems
