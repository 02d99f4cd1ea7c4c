"""The robot spec: one YAML document that becomes one registered robot class."""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, WrapValidator, model_validator
from pydantic_core import PydanticCustomError

from assembler.spec.expressions import (
    OFFSET_VARIABLES,
    ExpressionError,
    evaluate_expression,
    parse_expression,
)
from assembler.spec.schema.common import FiniteFloat, NonNegativeFloat, StrictModel, Vec3, Vec4
from assembler.spec.schema.joints import JointDefaults
from assembler.spec.schema.mjlab import MjlabOptions
from assembler.spec.schema.parts import Name, PartSpec
from assembler.spec.schema.robosuite import RobosuiteOptions

Morphology = Literal["manipulator", "legged_manipulator", "humanoid", "humanoid_upper_body", "legged"]
ARMLESS: tuple[str, ...] = ("legged",)
"""Morphologies without arms: a quadruped or a biped standing on ``feet``, no end effector, no gripper."""
Arm = Literal["right", "left"]
GROUPS: tuple[str, ...] = ("torso", "head", "legs", "base")
"""Body-part groups besides the arms, in robosuite's order of precedence."""


def _number_or_expression(value: Any, handler: Any) -> Any:
    """Accept a finite number, or an expression text that our own grammar can parse."""
    if isinstance(value, str):
        try:
            parse_expression(value)
        except ExpressionError as error:
            raise PydanticCustomError("offset_expression", str(error)) from None
        return value
    try:
        return handler(value)
    except Exception as error:  # pydantic's ValidationError, re-raised as one readable line
        raise PydanticCustomError(
            "offset_value",
            "expected a number or an expression such as '-0.16 - table_length / 2', got {value}",
            {"value": repr(value)},
        ) from error


OffsetValue = Annotated[FiniteFloat | str, WrapValidator(_number_or_expression)]
"""A number, or an expression over """ + ", ".join(OFFSET_VARIABLES) + " (no Python is evaluated)."

Offset3 = tuple[OffsetValue, OffsetValue, OffsetValue]


class GripperMount(StrictModel):
    """Where a gripper sits on an arm's end-effector body, replacing the gripper root's own pose."""

    pos: Vec3 | None = None
    """Position of the gripper root in the end-effector body's frame (metres); null keeps the gripper's."""

    quat: Vec4 | None = None
    """Orientation (w, x, y, z) of the gripper root in the end-effector body's frame; null keeps it."""


class JointGroups(StrictModel):
    """Which of the robot's joints belong to which body part: names or globs, as written in the MJCF."""

    torso: list[str] = Field(default_factory=list)
    """Torso joints (e.g. a waist or a lift)."""

    head: list[str] = Field(default_factory=list)
    """Head joints."""

    legs: list[str] = Field(default_factory=list)
    """Leg joints."""

    base: list[str] = Field(default_factory=list)
    """Joints that move the whole robot (mobile base joints inside the robot's own file)."""

    right: list[str] = Field(default_factory=list)
    """Joints of the right arm. With arm lists, a joint in no list belongs to no group (no controller
    drives it, e.g. a jaw declared as the gripper); with none, every joint not in another group is an
    arm joint."""

    left: list[str] = Field(default_factory=list)
    """Joints of the left arm (bimanual robots)."""


class RobotSpec(PartSpec):
    """A robot: its MJCF, morphology, arms, joint parameters, initial pose, offsets and default parts."""

    kind: Literal["robot"] = "robot"
    """What this document describes; robot specs may leave it out."""

    morphology: Morphology = "manipulator"
    """The model class the spec becomes: a manipulator, legged manipulator, (upper-body) humanoid, or a
    legged robot without arms (a quadruped, a biped: `feet`, no end effector, no gripper)."""

    feet: list[str] = Field(default_factory=list)
    """The bodies a legged robot stands on, as named in the MJCF (its feet or lowest leg links)."""

    arm_type: Literal["single", "bimanual"] = "single"
    """One arm (right) or two (right and left); humanoids are always bimanual."""

    eef_bodies: dict[Arm, str] = Field(default_factory=dict)
    """End-effector body per arm, as named in the MJCF; default right_hand (and left_hand)."""

    default_base: Name | None = None
    """The base the robot is assembled with by default (a registered base name), or null for none."""

    default_grippers: dict[Arm, Name | None] = Field(default_factory=dict)
    """The gripper assembled on each arm by default (a registered gripper name), or null for none."""

    gripper_mount: dict[Arm, GripperMount] = Field(default_factory=dict)
    """Per arm, the pose of the gripper on the end-effector body (robosuite's gripper_mount_*_offset)."""

    joint_groups: JointGroups | None = None
    """Body-part membership of the joints; null uses robosuite's name rules (torso, head, leg)."""

    remove_actuation: list[str] = Field(default_factory=list)
    """Joints (names or globs) removed with everything that drives or measures them (legged robots)."""

    remove_bodies: list[str] = Field(default_factory=list)
    """Bodies removed with everything below them and what drives or measures it: a jaw inside the
    arm's own file, made the robot's gripper by a gripper spec with root_body (docs/spec.md)."""

    remove_free_joint: bool = False
    """Remove the root's free joint, welding the robot to its base or the world."""

    add_free_joint: bool = False
    """Give the root body a free joint (a URDF cannot declare one): the robot stands on its own feet
    instead of being welded. The root body must have no joint of its own."""

    default_controller_config: dict[str, str] = Field(default_factory=dict)
    """Controller config name per body part (e.g. right: default_panda), for controller libraries."""

    robosuite: RobosuiteOptions = Field(default_factory=RobosuiteOptions)
    """How the robot enters robosuite's environments (docs/robosuite.md); every field has a default by
    arms, base and morphology."""

    mjlab: MjlabOptions = Field(default_factory=MjlabOptions)
    """What mjlab's tasks read of the robot (`assembler.mjlab.entity_cfg`): IMU, feet, joint-limit factor,
    spawn pose (docs/gpu.md); every field has a default."""

    base_xpos_offset: dict[str, Offset3] = Field(default_factory=dict)
    """Placement of the robot's base per arena (e.g. bins, empty, table); entries may use table_length.
    In robosuite's environments an arena left out takes robosuite's value for the arm type (Panda's for
    one arm, Baxter's for two)."""

    top_offset: Vec3 = (0.0, 0.0, 1.0)
    """Offset from the robot's root to its top, in metres (robosuite's placeholder is 0, 0, 1)."""

    horizontal_radius: NonNegativeFloat = 0.5
    """Radius of the robot's footprint in metres, for placing it clear of other objects."""

    bottom_offset: Vec3 | None = None
    """Vector from the root body to the robot's bottom without a base; null: the root's MJCF position."""

    joint_defaults: JointDefaults = Field(default_factory=JointDefaults)
    """Rules for frictionloss, damping and armature where the MJCF sets none (robosuite's by default)."""

    @model_validator(mode="after")
    def _arms_are_consistent(self) -> RobotSpec:
        arms = self.arms
        for field in ("eef_bodies", "default_grippers", "gripper_mount"):
            extra = sorted(set(getattr(self, field)) - set(arms))
            if extra:
                has = (
                    f"a {self.arm_type} robot has {', '.join(arms)}"
                    if arms
                    else f"a {self.morphology} robot has no arms"
                )
                raise ValueError(f"{field} names arm '{extra[0]}', but {has}")
        if self.morphology in ("humanoid", "humanoid_upper_body") and self.arm_type != "bimanual":
            raise ValueError(f"a {self.morphology} has two arms: set arm_type: bimanual")
        if self.feet and self.morphology not in ("legged", "legged_manipulator", "humanoid"):
            raise ValueError(
                f"feet: a {self.morphology} has no legs; set morphology: legged for a legged robot"
            )
        return self

    @property
    def arms(self) -> tuple[Arm, ...]:
        """The arms, right first; none for a morphology without arms."""
        if self.morphology in ARMLESS:
            return ()
        return ("right",) if self.arm_type == "single" else ("right", "left")

    def eef_body(self, arm: str) -> str:
        """The end-effector body of ``arm`` as named in the MJCF."""
        return self.eef_bodies.get(arm, f"{arm}_hand")  # type: ignore[call-overload, no-any-return]

    def resolve_base_xpos_offset(self, arena: str, **variables: float) -> tuple[float, float, float]:
        """The base offset for ``arena`` with expression variables bound (e.g. ``table_length=0.8``)."""
        if arena not in self.base_xpos_offset:
            known = ", ".join(self.base_xpos_offset) or "(none)"
            raise KeyError(f"robot {self.name!r} has no base_xpos_offset for {arena!r}; known: {known}")
        x, y, z = (evaluate_expression(v, variables) for v in self.base_xpos_offset[arena])
        return (x, y, z)
