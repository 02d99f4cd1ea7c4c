"""``validate``: spec files checked as a reviewer relies on, like a compiler: schema, every name the
specs give (registered parts, MJCF bodies, joints, sites, geoms, sensors), and optionally a compile.

Every problem of every spec is reported at once, each at its file, line and column. A spec whose
model file lives in a package that is not installed (robosuite's without the robosuite extra,
example-robot-data's without the urdf extra) is reported as not checked against it, never as checked.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from assembler.errors import AssemblerError, MissingPackageError, Problem
from assembler.models import PartModel, RobotModel
from assembler.registry.catalog import PARENTS, register_loaded
from assembler.registry.instances import equip
from assembler.registry.references import placement_reference_problems, spec_reference_problems
from assembler.spec.documents import LocatedDocument, validate
from assembler.spec.documents.problems import reading_order
from assembler.spec.schema import ExperimentSpec, SceneSpec
from assembler.spec.spec_files import load_documents, load_motors, read_spec_files

PLACEMENT_MODELS: dict[str, type[SceneSpec] | type[ExperimentSpec]] = {
    "scene": SceneSpec,
    "experiment": ExperimentSpec,
}


@dataclass
class MissingPackage:
    """A package some specs read their model file from, not installed here."""

    message: str
    """What is missing and what to install, e.g. ``Python package 'robosuite' is not installed; ...``."""

    specs: list[str] = field(default_factory=list)
    """The specs left unchecked for want of it."""


@dataclass
class ValidationReport:
    """What ``validate`` checked."""

    classes: list[type[PartModel]]
    """Every spec found, as its registered class."""

    compiled: list[str] = field(default_factory=list)
    """Specs compiled by MuJoCo (robots with their default base and grippers; bases and grippers alone)."""

    placements: list[str] = field(default_factory=list)
    """Scene and experiment files checked (their schema and the names they use)."""

    motors: list[str] = field(default_factory=list)
    """Motor specs checked (their schema and the consistency of their ratings), by name."""

    missing: dict[str, MissingPackage] = field(default_factory=dict)
    """Packages not installed, by name, with the specs that could not be checked against their file."""

    @property
    def unchecked(self) -> list[str]:
        """Specs not checked against their model file: the package holding it is not installed."""
        return [name for package in self.missing.values() for name in package.specs]


def _compile(cls: type[PartModel]) -> None:
    part = cls(idn=0)
    if isinstance(part, RobotModel):
        equip(part).get_model()
    else:
        part.compile_alone()


def _placement_problems(document: LocatedDocument) -> list[Problem]:
    model = PLACEMENT_MODELS[document.data["kind"]]
    try:
        loaded = validate(document, model)
    except AssemblerError as error:
        return error.problems
    return placement_reference_problems(document, loaded.spec.robots)


def validate_specs(paths: Sequence[str | Path], compile: bool = False) -> ValidationReport:
    """Register the part specs in ``paths`` and check each one, then the scene and experiment files
    among them; :class:`AssemblerError` lists every problem."""
    found = read_spec_files(paths)
    if found.problems:
        raise AssemblerError(found.problems)
    motors = load_motors(found.motors)
    classes = register_loaded(load_documents(found.parts, PARENTS), motors)
    report = ValidationReport(classes, placements=[document.file for document in found.placements])
    report.motors = [loaded.spec.name for loaded in motors]
    problems: list[Problem] = []
    for document in found.placements:
        problems += _placement_problems(document)
    for cls in classes:
        if cls.loaded is not None:
            problems += spec_reference_problems(cls.loaded)
        try:
            cls(idn=0).check()
            if compile:
                _compile(cls)
                report.compiled.append(cls.__name__)
        except MissingPackageError as error:
            message = error.problems[0].message.split(": ", 1)[-1]  # without the file reference
            report.missing.setdefault(error.package, MissingPackage(message)).specs.append(cls.__name__)
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise AssemblerError(sorted(problems, key=reading_order))
    return report
