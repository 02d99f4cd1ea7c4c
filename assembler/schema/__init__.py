"""Pydantic models of every spec format. No MuJoCo and no file I/O here: only shapes and rules."""

from assembler.schema.base import FiniteFloat, StrictModel, Vec3
from assembler.schema.joints import (
    JOINT_RULE_ATTRIBUTES,
    OVERRIDABLE_ATTRIBUTES,
    InverseIndexRule,
    JointDefaults,
    JointOverride,
    JointRule,
)
from assembler.schema.robot import RobotSpec

__all__ = [
    "JOINT_RULE_ATTRIBUTES",
    "OVERRIDABLE_ATTRIBUTES",
    "FiniteFloat",
    "InverseIndexRule",
    "JointDefaults",
    "JointOverride",
    "JointRule",
    "RobotSpec",
    "StrictModel",
    "Vec3",
]
