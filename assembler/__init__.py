"""robot-assembler: declarative YAML robot specs, assembled into MuJoCo models.

>>> import assembler
>>> robot = assembler.create_robot("Sparrow7", idn=0)
>>> model = robot.get_model()

``import assembler`` is light: each part of the API (and the shipped specs, registered when the
registry is first used) is imported on first use, so a command that only needs the command line or
the compiled-model cache never pays for the schema classes or for reading every spec; nor does
``assemble(name).get_model()`` of a robot asked for before (see :mod:`assembler.answers.deferred`).
"""

from __future__ import annotations

import importlib
from types import ModuleType
from typing import TYPE_CHECKING, Any

from assembler import compiler as _compiler
from assembler.errors import AssemblerError, JointAttributeError, MjcfError, Problem, RegistryError, SpecError
from assembler.version import __version__

if TYPE_CHECKING:  # for type checkers and editors; at run time each name is imported on first use
    from assembler.answers.load_model import load_model
    from assembler.models import (
        GripperModel,
        HumanoidModel,
        HumanoidUpperBodyModel,
        LeggedManipulatorModel,
        ManipulatorModel,
        RobotBaseModel,
        RobotModel,
    )
    from assembler.registry.catalog import (
        add_spec_folders,
        class_from_spec,
        load_shipped_specs,
        register_spec_string,
        register_specs,
        with_overrides,
    )
    from assembler.registry.instances import assemble, create_base, create_gripper, create_robot
    from assembler.registry.lookup import (
        REGISTERED_BASES,
        REGISTERED_GRIPPERS,
        REGISTERED_ROBOTS,
        RobotModelMeta,
        register_base,
        register_gripper,
        register_robot,
        registered_robot_names,
    )
    from assembler.spec.documents import LoadedSpec, Override, parse_overrides
    from assembler.spec.schema import BaseSpec, ExperimentSpec, GripperSpec, RobotSpec, SceneSpec
    from assembler.spec.spec_files import load_paths, load_string
    from assembler.worlds.experiment import Experiment, load_experiment
    from assembler.worlds.scene import Scene, build_scene, load_scene
    from assembler.worlds.variants import VariantPlan, write_variants

def _variant_patcher() -> ModuleType:
    """The patcher of robots with overrides (:mod:`assembler.patch.robot_variant`), loaded on a cache
    miss. The package root wires it into the compiler: the patcher reads the registry and the model
    classes, above the models that ask for it (see :data:`assembler.compiler.variant_patcher`)."""
    return importlib.import_module("assembler.patch.robot_variant")


_compiler.variant_patcher = _variant_patcher


_LAZY: dict[str, str] = {
    # assemble and create_robot answer a robot asked for before from the cache, reading no spec
    # (assembler.answers.deferred); type checkers see the registry's own (a deferred robot is one).
    "assemble": "assembler.answers.deferred",
    "create_base": "assembler.registry.instances",
    "create_gripper": "assembler.registry.instances",
    "create_robot": "assembler.answers.deferred",
    "add_spec_folders": "assembler.registry.catalog",
    "class_from_spec": "assembler.registry.catalog",
    "load_shipped_specs": "assembler.registry.catalog",
    "register_spec_string": "assembler.registry.catalog",
    "register_specs": "assembler.registry.catalog",
    "with_overrides": "assembler.registry.catalog",
    "LoadedSpec": "assembler.spec.documents",
    "Override": "assembler.spec.documents",
    "parse_overrides": "assembler.spec.documents",
    "Experiment": "assembler.worlds.experiment",
    "load_experiment": "assembler.worlds.experiment",
    "load_paths": "assembler.spec.spec_files",
    "load_string": "assembler.spec.spec_files",
    "load_model": "assembler.answers.load_model",
    "GripperModel": "assembler.models",
    "HumanoidModel": "assembler.models",
    "HumanoidUpperBodyModel": "assembler.models",
    "LeggedManipulatorModel": "assembler.models",
    "ManipulatorModel": "assembler.models",
    "RobotBaseModel": "assembler.models",
    "RobotModel": "assembler.models",
    "REGISTERED_BASES": "assembler.registry.lookup",
    "REGISTERED_GRIPPERS": "assembler.registry.lookup",
    "REGISTERED_ROBOTS": "assembler.registry.lookup",
    "RobotModelMeta": "assembler.registry.lookup",
    "register_base": "assembler.registry.lookup",
    "register_gripper": "assembler.registry.lookup",
    "register_robot": "assembler.registry.lookup",
    "registered_robot_names": "assembler.registry.lookup",
    "Scene": "assembler.worlds.scene",
    "build_scene": "assembler.worlds.scene",
    "load_scene": "assembler.worlds.scene",
    "BaseSpec": "assembler.spec.schema",
    "ExperimentSpec": "assembler.spec.schema",
    "GripperSpec": "assembler.spec.schema",
    "RobotSpec": "assembler.spec.schema",
    "SceneSpec": "assembler.spec.schema",
    "VariantPlan": "assembler.worlds.variants",
    "write_variants": "assembler.worlds.variants",
}
"""Each public name imported on first use, and the module it comes from."""

SUBPACKAGES: tuple[str, ...] = (
    "answers",
    "cache",
    "cli",
    "compiler",
    "files",
    "importers",
    "mjcf",
    "models",
    "patch",
    "registry",
    "spec",
    "tools",
    "urdf",
    "worlds",
)
"""Modules reachable as attributes (``assembler.cache``) once anything asks for them."""


def __getattr__(name: str) -> Any:
    if name in _LAZY:
        value = getattr(importlib.import_module(_LAZY[name]), name)
        globals()[name] = value
        return value
    if name in SUBPACKAGES:
        return importlib.import_module(f"assembler.{name}")
    raise AttributeError(f"module 'assembler' has no attribute '{name}'")


def __dir__() -> list[str]:
    return sorted({*globals(), *_LAZY, *SUBPACKAGES})


__all__ = [
    "REGISTERED_BASES",
    "REGISTERED_GRIPPERS",
    "REGISTERED_ROBOTS",
    "BaseSpec",
    "GripperModel",
    "GripperSpec",
    "HumanoidModel",
    "HumanoidUpperBodyModel",
    "LeggedManipulatorModel",
    "RobotBaseModel",
    "Scene",
    "SceneSpec",
    "assemble",
    "build_scene",
    "create_base",
    "create_gripper",
    "load_scene",
    "Experiment",
    "ExperimentSpec",
    "Override",
    "VariantPlan",
    "load_experiment",
    "load_model",
    "parse_overrides",
    "with_overrides",
    "write_variants",
    "register_base",
    "register_gripper",
    "AssemblerError",
    "JointAttributeError",
    "LoadedSpec",
    "ManipulatorModel",
    "MjcfError",
    "Problem",
    "RegistryError",
    "RobotModel",
    "RobotModelMeta",
    "RobotSpec",
    "SpecError",
    "__version__",
    "add_spec_folders",
    "class_from_spec",
    "create_robot",
    "load_paths",
    "load_shipped_specs",
    "load_string",
    "register_robot",
    "register_spec_string",
    "register_specs",
    "registered_robot_names",
]
