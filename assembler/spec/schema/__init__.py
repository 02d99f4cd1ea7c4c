"""Pydantic models of every spec format. No MuJoCo and no file I/O here: only shapes and rules."""

from assembler.spec.schema.actuators import ActuatorDeclaration, ActuatorType
from assembler.spec.schema.base_spec import BaseSpec, BaseType
from assembler.spec.schema.common import FiniteFloat, StrictModel, Vec3, Vec4
from assembler.spec.schema.experiment import ExperimentRobot, ExperimentSpec
from assembler.spec.schema.gripper import GripperSpec
from assembler.spec.schema.joints import (
    JOINT_RULE_ATTRIBUTES,
    OVERRIDABLE_ATTRIBUTES,
    InverseIndexRule,
    JointDefaults,
    JointOverride,
    JointRule,
)
from assembler.spec.schema.motor import JointMotor, MotorSpec
from assembler.spec.schema.parts import PartSpec
from assembler.spec.schema.physical import BODY_SCALES, BodyScale, GeomFriction
from assembler.spec.schema.robot import GROUPS, Arm, GripperMount, JointGroups, RobotSpec
from assembler.spec.schema.scene import SceneRobot, SceneSpec

SPEC_KINDS: dict[str, type[PartSpec]] = {"robot": RobotSpec, "base": BaseSpec, "gripper": GripperSpec}
"""The model of each part spec's ``kind`` (robot specs may leave ``kind`` out)."""

__all__ = [
    "BODY_SCALES",
    "GROUPS",
    "JOINT_RULE_ATTRIBUTES",
    "OVERRIDABLE_ATTRIBUTES",
    "SPEC_KINDS",
    "ActuatorDeclaration",
    "ActuatorType",
    "Arm",
    "BaseSpec",
    "BaseType",
    "BodyScale",
    "ExperimentRobot",
    "ExperimentSpec",
    "FiniteFloat",
    "GeomFriction",
    "GripperMount",
    "GripperSpec",
    "InverseIndexRule",
    "JointDefaults",
    "JointGroups",
    "JointOverride",
    "JointMotor",
    "JointRule",
    "MotorSpec",
    "PartSpec",
    "RobotSpec",
    "SceneRobot",
    "SceneSpec",
    "StrictModel",
    "Vec3",
    "Vec4",
]
