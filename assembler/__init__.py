"""robot-assembler: declarative YAML robot specs, assembled into MuJoCo models.

>>> import assembler
>>> robot = assembler.create_robot("Sparrow7", idn=0)
>>> model = robot.get_model()

``import assembler`` is light: each part of the API (and the shipped specs, registered when the
registry is first used) is imported on first use, so a command that only needs the command line or
the compiled-model cache never pays for the schema classes or for reading every spec; nor does
``assemble(name).get_model()`` of a robot asked for before (see :mod:`assembler.answers.deferred`).

The API is declared once, in :data:`API`: ``__all__``, ``dir(assembler)`` and the imports on first use
are made from it. The imports under ``TYPE_CHECKING`` repeat it for type checkers and editors, which
cannot read a table; a test holds the two equal, and ``docs/api.md`` is generated from :data:`API`.
"""

from __future__ import annotations

import importlib
from types import ModuleType
from typing import TYPE_CHECKING, Any

from assembler import compiler as _compiler

if TYPE_CHECKING:  # for type checkers and editors: API below, as imports (a test holds them equal)
    from assembler.answers.load_model import load_model as load_model
    from assembler.errors import AssemblerError as AssemblerError
    from assembler.errors import JointAttributeError as JointAttributeError
    from assembler.errors import MjcfError as MjcfError
    from assembler.errors import Problem as Problem
    from assembler.errors import RegistryError as RegistryError
    from assembler.errors import SpecError as SpecError
    from assembler.models import GripperModel as GripperModel
    from assembler.models import HumanoidModel as HumanoidModel
    from assembler.models import HumanoidUpperBodyModel as HumanoidUpperBodyModel
    from assembler.models import LeggedManipulatorModel as LeggedManipulatorModel
    from assembler.models import LeggedModel as LeggedModel
    from assembler.models import ManipulatorModel as ManipulatorModel
    from assembler.models import RobotBaseModel as RobotBaseModel
    from assembler.models import RobotModel as RobotModel
    from assembler.registry.catalog import add_spec_folders as add_spec_folders
    from assembler.registry.catalog import class_from_spec as class_from_spec
    from assembler.registry.catalog import load_shipped_specs as load_shipped_specs
    from assembler.registry.catalog import register_spec_string as register_spec_string
    from assembler.registry.catalog import register_specs as register_specs
    from assembler.registry.catalog import with_overrides as with_overrides
    from assembler.registry.instances import assemble as assemble
    from assembler.registry.instances import create_base as create_base
    from assembler.registry.instances import create_gripper as create_gripper
    from assembler.registry.instances import create_robot as create_robot
    from assembler.registry.lookup import REGISTERED_BASES as REGISTERED_BASES
    from assembler.registry.lookup import REGISTERED_GRIPPERS as REGISTERED_GRIPPERS
    from assembler.registry.lookup import REGISTERED_ROBOTS as REGISTERED_ROBOTS
    from assembler.registry.lookup import RobotModelMeta as RobotModelMeta
    from assembler.registry.lookup import register_base as register_base
    from assembler.registry.lookup import register_gripper as register_gripper
    from assembler.registry.lookup import register_robot as register_robot
    from assembler.registry.lookup import registered_robot_names as registered_robot_names
    from assembler.spec.documents import LoadedSpec as LoadedSpec
    from assembler.spec.documents import Override as Override
    from assembler.spec.documents import parse_overrides as parse_overrides
    from assembler.spec.schema import BaseSpec as BaseSpec
    from assembler.spec.schema import ExperimentSpec as ExperimentSpec
    from assembler.spec.schema import GripperSpec as GripperSpec
    from assembler.spec.schema import RobotSpec as RobotSpec
    from assembler.spec.schema import SceneSpec as SceneSpec
    from assembler.spec.spec_files import load_paths as load_paths
    from assembler.spec.spec_files import load_string as load_string
    from assembler.version import __version__ as __version__
    from assembler.worlds.experiment import Experiment as Experiment
    from assembler.worlds.experiment import load_experiment as load_experiment
    from assembler.worlds.scene import Scene as Scene
    from assembler.worlds.scene import build_scene as build_scene
    from assembler.worlds.scene import load_scene as load_scene
    from assembler.worlds.variants import VariantPlan as VariantPlan
    from assembler.worlds.variants import write_variants as write_variants


def _variant_patcher() -> ModuleType:
    """The patcher of robots with overrides (:mod:`assembler.patch.robot_variant`), loaded on a cache
    miss. The package root wires it into the compiler: the patcher reads the registry and the model
    classes, above the models that ask for it (see :data:`assembler.compiler.variant_patcher`)."""
    return importlib.import_module("assembler.patch.robot_variant")


_compiler.variant_patcher = _variant_patcher


API: dict[str, tuple[str, ...]] = {
    # a robot, assembled or piece by piece, and its compiled model
    "assembler.registry.instances": ("assemble", "create_robot", "create_base", "create_gripper"),
    "assembler.answers.load_model": ("load_model",),
    # the registries, by name, as robosuite has them
    "assembler.registry.lookup": (
        "REGISTERED_ROBOTS",
        "REGISTERED_BASES",
        "REGISTERED_GRIPPERS",
        "register_robot",
        "register_base",
        "register_gripper",
        "registered_robot_names",
        "RobotModelMeta",
    ),
    # specs registered as classes
    "assembler.registry.catalog": (
        "register_specs",
        "register_spec_string",
        "add_spec_folders",
        "load_shipped_specs",
        "class_from_spec",
        "with_overrides",
    ),
    # spec files read and validated, and overrides
    "assembler.spec.spec_files": ("load_paths", "load_string"),
    "assembler.spec.documents": ("LoadedSpec", "Override", "parse_overrides"),
    "assembler.spec.schema": ("RobotSpec", "BaseSpec", "GripperSpec", "SceneSpec", "ExperimentSpec"),
    # the model classes a spec becomes
    "assembler.models": (
        "RobotModel",
        "ManipulatorModel",
        "LeggedManipulatorModel",
        "LeggedModel",
        "HumanoidModel",
        "HumanoidUpperBodyModel",
        "RobotBaseModel",
        "GripperModel",
    ),
    # scenes, experiments and variants
    "assembler.worlds.scene": ("Scene", "build_scene", "load_scene"),
    "assembler.worlds.experiment": ("Experiment", "load_experiment"),
    "assembler.worlds.variants": ("VariantPlan", "write_variants"),
    # errors, one line per problem
    "assembler.errors": (
        "AssemblerError",
        "SpecError",
        "MjcfError",
        "RegistryError",
        "JointAttributeError",
        "Problem",
    ),
    "assembler.version": ("__version__",),
}
"""The public API, declared once: each module and the names it gives, imported on first use."""

ANSWERED_FROM_THE_CACHE: dict[str, str] = {
    "assemble": "assembler.answers.deferred",
    "create_robot": "assembler.answers.deferred",
}
"""Names that run from another module than :data:`API`'s, with the same signature: these answer a
robot asked for before from the cache, reading no spec (:mod:`assembler.answers.deferred`); type
checkers and the API reference see the registry's own (a deferred robot is one)."""

_SOURCES: dict[str, str] = {
    name: ANSWERED_FROM_THE_CACHE.get(name, module) for module, names in API.items() for name in names
}
"""Each public name and the module it is imported from on first use."""

SUBPACKAGES: tuple[str, ...] = (
    "answers",
    "cache",
    "cli",
    "compiler",
    "errors",
    "files",
    "importers",
    "mjcf",
    "models",
    "patch",
    "registry",
    "spec",
    "tools",
    "urdf",
    "version",
    "worlds",
)
"""Modules reachable as attributes (``assembler.cache``) once anything asks for them."""

__all__ = list(_SOURCES)


def __getattr__(name: str) -> Any:
    if name in _SOURCES:
        value = getattr(importlib.import_module(_SOURCES[name]), name)
        globals()[name] = value
        return value
    if name in SUBPACKAGES:
        return importlib.import_module(f"assembler.{name}")
    raise AttributeError(f"module 'assembler' has no attribute '{name}'")


def __dir__() -> list[str]:
    return sorted({*globals(), *_SOURCES, *SUBPACKAGES})
