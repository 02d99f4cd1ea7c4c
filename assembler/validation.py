"""``validate``: spec files checked as a reviewer relies on, like a compiler: schema, every name the
specs give (registered parts, MJCF bodies, joints, sites, geoms, sensors), and optionally a compile.

Every problem of every spec is reported at once, each at its file, line and column. A spec whose
MJCF lives in a package that is not installed (robosuite's, without the extra) is reported as not
checked against its MJCF, never as checked.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

from assembler.assembly import equip
from assembler.catalog import register_specs
from assembler.errors import AssemblerError, MissingPackageError, Problem
from assembler.models import PartModel, RobotModel
from assembler.references import spec_reference_problems


@dataclass
class ValidationReport:
    """What ``validate`` checked."""

    classes: list[type[PartModel]]
    """Every spec found, as its registered class."""

    compiled: list[str] = field(default_factory=list)
    """Specs compiled by MuJoCo (robots with their default base and grippers; bases and grippers alone)."""

    unchecked: list[str] = field(default_factory=list)
    """Specs not checked against their MJCF: the package holding it is not installed."""

    missing: str = ""
    """What to install to check the unchecked ones."""


def _compile(cls: type[PartModel]) -> None:
    part = cls(idn=0)
    if isinstance(part, RobotModel):
        equip(part).get_model()
    else:
        part.compile_alone()


def validate_specs(paths: Sequence[str | Path], compile: bool = False) -> ValidationReport:
    """Register the specs in ``paths`` and check each one; :class:`AssemblerError` lists every problem."""
    classes = register_specs(*paths)
    report = ValidationReport(classes)
    problems: list[Problem] = []
    for cls in classes:
        if cls.loaded is not None:
            problems += spec_reference_problems(cls.loaded)
        try:
            cls(idn=0).check()
            if compile:
                _compile(cls)
                report.compiled.append(cls.__name__)
        except MissingPackageError as error:
            report.unchecked.append(cls.__name__)
            report.missing = error.problems[0].message.split(": ", 1)[-1]
        except AssemblerError as error:
            problems.extend(error.problems)
    if problems:
        raise AssemblerError(problems)
    return report
