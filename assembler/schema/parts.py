"""Fields every part spec shares (robot, base, gripper): identity, MJCF file and joint parameters."""

from __future__ import annotations

from typing import Annotated

from pydantic import Field

from assembler.schema.common import FiniteFloat, StrictModel
from assembler.schema.fixes import MjcfFix
from assembler.schema.joints import JointDefaults, JointOverride

NAME_PATTERN = r"^[A-Za-z][A-Za-z0-9_]*$"

Name = Annotated[str, Field(pattern=NAME_PATTERN, max_length=64)]
"""A registry name: it becomes a Python class name, so letters, digits and underscores."""

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

    mjcf: str = Field(min_length=1)
    """The MJCF file: relative to this spec file, absolute, or 'package://<python package>/<path>'."""

    mjcf_fixes: list[MjcfFix] = Field(default_factory=list)
    """Declared repairs of an MJCF file we do not own, applied before MuJoCo reads it (each says why)."""

    init_qpos: list[FiniteFloat] | None = None
    """Initial positions of this part's joints, in MuJoCo's order; null keeps the MJCF's qpos0."""

    joint_defaults: JointDefaults = Field(default_factory=lambda: NO_RULES)
    """Rules for frictionloss, damping and armature where the MJCF sets none (none for bases and grippers)."""

    joints: list[JointOverride] = Field(default_factory=list)
    """Per-joint overrides, applied in order after the default rules."""
