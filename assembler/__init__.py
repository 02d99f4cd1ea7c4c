"""robot-assembler: declarative YAML robot specs, assembled into MuJoCo models.

>>> import assembler
>>> robot = assembler.create_robot("Sparrow7", idn=0)
>>> model = robot.get_model()
"""

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
from assembler.errors import (
    AssemblerError,
    JointAttributeError,
    MjcfError,
    Problem,
    RegistryError,
    SpecError,
)
from assembler.experiment import Experiment, load_experiment
from assembler.loader import load_paths, load_string
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
from assembler.version import __version__

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

load_shipped_specs()
