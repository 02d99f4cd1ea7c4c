"""Spec folders and experiment files named outside the code, for training scripts nobody edits.

A script that only calls ``robosuite.make`` can still get spec robots: name spec folders in
``ASSEMBLER_ROBOSUITE_SPECS`` (separated like ``PATH``) or an experiment file in
``ASSEMBLER_ROBOSUITE_EXPERIMENT``, and either run the script with
``python -m assembler.robosuite script.py ...`` or install the start-up hook once
(``python -m assembler.robosuite --install-hook``), which registers them when the process imports
robosuite, and costs nothing in processes that never do.

An experiment file's robots enter robosuite under their names with the experiment's overrides,
base and grippers as their defaults: the robosuite class of that name is the experiment's robot.
"""

from __future__ import annotations

import os
import warnings
from collections.abc import Callable
from pathlib import Path

from assembler import models
from assembler.errors import AssemblerError, AssemblerWarning, RegistryError
from assembler.robosuite.conventions import offered
from assembler.robosuite.registries import install
from assembler.spec.part_arguments import DEFAULT

SPECS_VARIABLE = "ASSEMBLER_ROBOSUITE_SPECS"
EXPERIMENT_VARIABLE = "ASSEMBLER_ROBOSUITE_EXPERIMENT"


def register(*paths: str | Path, replace_robosuite: bool = False) -> list[str]:
    """Register the specs in ``paths`` (files and folders) with the assembler and robosuite: all or
    none. A name robosuite uses itself is an error unless ``replace_robosuite``; returns the names."""
    from assembler.registry.catalog import register_specs

    classes = register_specs(*paths)
    return install([cls for cls in classes if offered(cls)], replace=replace_robosuite)


def experiment_robots(path: str | Path) -> list[type[models.ManipulatorModel]]:
    """The robots of an experiment file, each a class with the experiment's overrides and parts; every
    problem of the file at once, at its line."""
    from assembler.registry.catalog import with_overrides
    from assembler.worlds.experiment import build_experiment, read_experiment

    loaded = read_experiment(path)
    built = build_experiment(loaded)
    classes: dict[str, type[models.ManipulatorModel]] = {}
    for index, (entry, robot) in enumerate(zip(loaded.spec.robots, built.robots, strict=True)):
        parts: dict[str, object] = {}
        if entry.base != DEFAULT:
            parts["default_base"] = entry.base
        for arm, gripper in entry.grippers.items():
            parts[f"default_grippers.{arm}"] = gripper
        label = f"{path}: robots[{index}]."
        cls = with_overrides(type(robot), parts, label) if parts else type(robot)
        if {"pos", "ori"} & entry.model_fields_set:
            message = (
                f"{label} pos and ori are not used in robosuite: its environments place each robot themselves"
            )
            warnings.warn(message, AssemblerWarning, stacklevel=2)
        name = cls.__name__
        if name in classes and classes[name].spec != cls.spec:
            raise RegistryError(
                f"{label} robot {name} appears twice with different settings; robosuite has one {name}"
            )
        if not isinstance(robot, models.ManipulatorModel):
            raise RegistryError(
                f"{label} robot {name} has no arms; robosuite's environments take robots with arms"
            )
        classes[name] = cls  # type: ignore[assignment]
    return list(classes.values())


def register_experiment(path: str | Path) -> list[str]:
    """Register an experiment file's robots with robosuite: the file is the user's explicit choice, so
    each replaces the class robosuite had under its name (robosuite's own is logged as replaced)."""
    robots: list[type[models.PartModel]] = list(experiment_robots(path))
    return install(robots, replace=True, replace_ours=True)


def register_from_environment() -> list[str]:
    """Register what ``ASSEMBLER_ROBOSUITE_SPECS`` and ``ASSEMBLER_ROBOSUITE_EXPERIMENT`` name. Each
    variable's specs enter all or none; a problem is not raised (robosuite is being imported, and its
    import must not fail because of a variable) but returned, one line per problem, naming the variable."""
    said: list[str] = []
    folders = [folder for folder in os.environ.get(SPECS_VARIABLE, "").split(os.pathsep) if folder]
    experiment = os.environ.get(EXPERIMENT_VARIABLE)
    steps: list[tuple[str, Callable[[], list[str]]]] = []
    if folders:
        steps.append((SPECS_VARIABLE, lambda: register(*folders)))
    if experiment:
        steps.append((EXPERIMENT_VARIABLE, lambda: register_experiment(experiment)))
    for variable, step in steps:
        try:
            step()
        except AssemblerError as error:
            said += [f"{problem} ({variable}: nothing of it was registered)" for problem in error.problems]
    return said
