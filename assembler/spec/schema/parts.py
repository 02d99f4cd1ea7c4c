"""Fields every part spec shares (robot, base, gripper): identity, MJCF or URDF file, joints, actuators."""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from assembler.spec.schema.actuators import ActuatorDeclaration
from assembler.spec.schema.common import FiniteFloat, StrictModel, rule_error
from assembler.spec.schema.common import Name as Name  # where the other schemas find it
from assembler.spec.schema.fixes import MjcfFix
from assembler.spec.schema.joints import JointDefaults, JointOverride
from assembler.spec.schema.lint import LintOptions
from assembler.spec.schema.motor import JointMotor
from assembler.spec.schema.physical import BodyScale, GeomFriction

NO_RULES = JointDefaults(frictionloss=None, damping=None, armature=None)
"""Bases and grippers keep their MJCF's joint values unless their spec says otherwise (as in robosuite)."""


class PartSpec(StrictModel):
    """What robots, bases and grippers have in common."""

    name: Name
    """The registry name; `create_robot`, `create_base` and `create_gripper` take it."""

    extends: str | None = None
    """A registered name of the same kind, or a spec file (relative to this file), to inherit fields from."""

    description: str = ""
    """One or two sentences for `assembler list` and the generated docs."""

    mjcf: str | None = Field(default=None, min_length=1)
    """The MJCF file: relative to this spec file, absolute, or 'package://<python package>/<path>'. Give
    exactly one of mjcf and urdf."""

    urdf: str | None = Field(default=None, min_length=1)
    """The URDF file, imported by MuJoCo: relative to this spec file, absolute, or 'package://<package>/<path>'
    (an installed Python package of that name, else a ROS package: one the spec repository declares in
    packages, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH or the share/ folders of the Python environment, where
    example-robot-data installs)."""

    balance_inertia: bool = False
    """URDF only: make link inertias that violate A + B >= C (a common export error MuJoCo refuses)
    isotropic at their mean moment, as MuJoCo's balanceinertia does; `assembler inspect` names them."""

    mjcf_fixes: list[MjcfFix] = Field(default_factory=list)
    """Declared repairs of an MJCF file we do not own, applied before MuJoCo reads it (each says why)."""

    init_qpos: list[FiniteFloat] | None = None
    """Initial positions of this part's joints, in MuJoCo's order; null keeps the MJCF's qpos0."""

    joint_defaults: JointDefaults = Field(default_factory=lambda: NO_RULES)
    """Rules for frictionloss, damping and armature where the MJCF sets none (none for bases and grippers)."""

    joints: list[JointOverride] = Field(default_factory=list)
    """Per-joint overrides, applied in order after the default rules."""

    bodies: list[BodyScale] = Field(default_factory=list)
    """Mass and size factors of bodies (names or globs), applied in order (a later entry wins)."""

    geoms: list[GeomFriction] = Field(default_factory=list)
    """Friction of geoms (names or globs), applied in order (a later entry wins)."""

    actuators: list[ActuatorDeclaration] = Field(default_factory=list)
    """Actuators to add, one per matched joint; a later entry replaces an earlier one's on the same joint."""

    motors: list[JointMotor] = Field(default_factory=list)
    """Motors on the joints whose names match: each joint's armature, damping and frictionloss from the
    motor and gearbox (unless ``joints:`` sets them), and an actuator that replaces the joint's own
    (docs/motors.md); a later entry replaces an earlier one on the same joint."""

    contact_excludes: list[tuple[str, str]] = Field(default_factory=list)
    """Pairs of bodies (as named in the file) that never collide, e.g. links whose collision meshes
    overlap where they meet (MuJoCo's <contact><exclude>)."""

    collision_colour: Literal["file", "robosuite"] = "file"
    """file: every geom keeps the colour and material its file gives; robosuite: collision geoms
    (group 0) lose their material and take robosuite's collision colour (green for robots, blue for
    grippers, yellow for mounts), as in robosuite's own models (`assembler inspect` says so)."""

    lint: LintOptions = Field(default_factory=LintOptions)
    """Lint findings about this part that its authors accept, each with the reason."""

    @model_validator(mode="after")
    def _one_source_file(self) -> PartSpec:
        if (self.mjcf is None) == (self.urdf is None):
            given = "both" if self.mjcf is not None else "neither"
            raise rule_error(f"give exactly one of mjcf and urdf (the model file), got {given}")
        if self.urdf is not None and self.mjcf_fixes:
            raise rule_error("mjcf_fixes repair MJCF files; a spec with urdf cannot use them")
        if self.mjcf is not None and self.balance_inertia:
            raise rule_error("balance_inertia applies to URDF files; fix the MJCF's <inertial> instead")
        if getattr(self, "remove_free_joint", False) and getattr(self, "add_free_joint", False):
            raise rule_error("give remove_free_joint or add_free_joint, not both")
        return self

    @property
    def source_field(self) -> str:
        """'mjcf' or 'urdf': the field naming this part's model file."""
        return "urdf" if self.urdf is not None else "mjcf"

    @property
    def source_file(self) -> str:
        """The model file reference (resolved by the loader), MJCF or URDF."""
        return self.urdf if self.urdf is not None else (self.mjcf or "")
