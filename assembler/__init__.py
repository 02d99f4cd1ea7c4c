"""robot-assembler: declarative YAML robot specs, assembled into MuJoCo models.

>>> import assembler
>>> robot = assembler.create_robot("Sparrow7", idn=0)
>>> model = robot.get_model()
"""

from assembler.catalog import (
    add_spec_folders,
    class_from_spec,
    load_shipped_specs,
    register_spec_string,
    register_specs,
)
from assembler.errors import (
    AssemblerError,
    JointAttributeError,
    MjcfError,
    Problem,
    RegistryError,
    SpecError,
)
from assembler.loader import LoadedSpec, load_paths, load_string
from assembler.models import ManipulatorModel, RobotModel
from assembler.registry import (
    REGISTERED_ROBOTS,
    RobotModelMeta,
    create_robot,
    register_robot,
    registered_robot_names,
)
from assembler.schema import RobotSpec

__version__ = "0.1.0"

__all__ = [
    "REGISTERED_ROBOTS",
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
