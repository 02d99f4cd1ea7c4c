"""robot-assembler: declarative YAML robot specs, assembled into MuJoCo models.

>>> import assembler
>>> robot = assembler.create_robot("Sparrow7", idn=0)
>>> model = robot.get_model()

``import assembler`` is light: each part of the API (and the shipped specs, registered when the
registry is first used) is imported on first use, so a command that only needs the command line or
the compiled-model cache never pays for the schema classes or for reading every spec.
"""

from __future__ import annotations

import importlib
from typing import TYPE_CHECKING, Any

from assembler.errors import AssemblerError, JointAttributeError, MjcfError, Problem, RegistryError, SpecError
from assembler.version import __version__

if TYPE_CHECKING:  # for type checkers and editors; at run time each name is imported on first use
    from assembler.assembly import assemble, create_base, create_gripper, create_robot
    from assembler.catalog import (
        add_spec_folders,
        class_from_spec,
        load_shipped_specs,
        register_spec_string,
        register_specs,
        with_overrides,
    )
    from assembler.documents import LoadedSpec, Override, parse_overrides
    from assembler.experiment import Experiment, load_experiment
    from assembler.loader import load_paths, load_string
    from assembler.loading import load_model
    from assembler.models import (
        GripperModel,
        HumanoidModel,
        HumanoidUpperBodyModel,
        LeggedManipulatorModel,
        ManipulatorModel,
        RobotBaseModel,
        RobotModel,
    )
    from assembler.registry import (
        REGISTERED_BASES,
        REGISTERED_GRIPPERS,
        REGISTERED_ROBOTS,
        RobotModelMeta,
        register_base,
        register_gripper,
        register_robot,
        registered_robot_names,
    )
    from assembler.scene import Scene, build_scene, load_scene
    from assembler.schema import BaseSpec, ExperimentSpec, GripperSpec, RobotSpec, SceneSpec
    from assembler.variants import VariantPlan, write_variants

_LAZY: dict[str, str] = {
    "assemble": "assembler.assembly",
    "create_base": "assembler.assembly",
    "create_gripper": "assembler.assembly",
    "create_robot": "assembler.assembly",
    "add_spec_folders": "assembler.catalog",
    "class_from_spec": "assembler.catalog",
    "load_shipped_specs": "assembler.catalog",
    "register_spec_string": "assembler.catalog",
    "register_specs": "assembler.catalog",
    "with_overrides": "assembler.catalog",
    "LoadedSpec": "assembler.documents",
    "Override": "assembler.documents",
    "parse_overrides": "assembler.documents",
    "Experiment": "assembler.experiment",
    "load_experiment": "assembler.experiment",
    "load_paths": "assembler.loader",
    "load_string": "assembler.loader",
    "load_model": "assembler.loading",
    "GripperModel": "assembler.models",
    "HumanoidModel": "assembler.models",
    "HumanoidUpperBodyModel": "assembler.models",
    "LeggedManipulatorModel": "assembler.models",
    "ManipulatorModel": "assembler.models",
    "RobotBaseModel": "assembler.models",
    "RobotModel": "assembler.models",
    "REGISTERED_BASES": "assembler.registry",
    "REGISTERED_GRIPPERS": "assembler.registry",
    "REGISTERED_ROBOTS": "assembler.registry",
    "RobotModelMeta": "assembler.registry",
    "register_base": "assembler.registry",
    "register_gripper": "assembler.registry",
    "register_robot": "assembler.registry",
    "registered_robot_names": "assembler.registry",
    "Scene": "assembler.scene",
    "build_scene": "assembler.scene",
    "load_scene": "assembler.scene",
    "BaseSpec": "assembler.schema",
    "ExperimentSpec": "assembler.schema",
    "GripperSpec": "assembler.schema",
    "RobotSpec": "assembler.schema",
    "SceneSpec": "assembler.schema",
    "VariantPlan": "assembler.variants",
    "write_variants": "assembler.variants",
}
"""Each public name imported on first use, and the module it comes from."""

SUBPACKAGES: tuple[str, ...] = (
    "cache",
    "catalog",
    "cli",
    "diff",
    "documents",
    "lint",
    "loader",
    "mjcf",
    "models",
    "paths",
    "references",
    "registry",
    "render",
    "scene",
    "schema",
    "validation",
    "variants",
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
