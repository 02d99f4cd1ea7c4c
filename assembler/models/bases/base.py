"""RobotBaseModel: what a robot stands on. Each base type (mount, mobile, legged, null) is a subclass
in its own module that owns its prefix, how it carries a robot, and what it needs to compile alone."""

from __future__ import annotations

from typing import Any, ClassVar

import mujoco
import numpy as np

from assembler.errors import Problem
from assembler.mjcf import census
from assembler.mjcf.census import Census
from assembler.models.groups import robosuite_group
from assembler.models.joint_rules import matching_joints
from assembler.models.part import FloatArray, PartModel
from assembler.models.preparation import PreparedPart
from assembler.models.registering import REGISTRIES, Registry
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import BaseSpec

REGISTERED_BASES: Registry[RobotBaseModel] = REGISTRIES["base"]
"""Every registered base class by name."""


class RobotBaseModel(PartModel):
    """A base built from its spec; its type's subclass decides how it carries the robot."""

    in_registry = False
    family: ClassVar[str] = "base"
    registry: ClassVar[Registry[Any]] = REGISTERED_BASES
    spec: ClassVar[BaseSpec]
    collision_rgba = (0.5, 0.5, 0.0, 1.0)  # robosuite's MOUNT_COLLISION_COLOR

    prefix_stem: ClassVar[str] = "base"
    """robosuite's prefix for this type of base, before the idn (``mobilebase`` -> ``mobilebase0_``)."""

    default_group: ClassVar[str] = "base"
    """The body part a joint of this base belongs to when neither the spec nor its name says."""

    @property
    def type(self) -> str:
        """mount, mobile, legged or null."""
        return self.spec.type

    @property
    def naming_prefix(self) -> str:
        """``fixed_mount{idn}_``, ``mobilebase{idn}_``, ``leg{idn}_`` or ``nullbase{idn}_``."""
        return f"{self.prefix_stem}{self.idn}_"

    def census_contribution(self, robot_root: mujoco.MjsBody) -> Census:
        """How many elements of each kind carrying a robot (whose root body is ``robot_root``) adds
        to an assembly: all of this base's own, unless its type says otherwise."""
        return census.of_spec(self.prepared_mjspec)

    def carry(
        self, assembly: mujoco.MjSpec, robot: mujoco.MjSpec, robot_prefix: str, offset: FloatArray
    ) -> None:
        """Attach the robot's part spec (not yet attached) and this base to ``assembly``; ``offset`` is
        robosuite's mount offset (the robot root's MJCF position minus this base's top offset)."""
        raise NotImplementedError

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        check = self.name_check(prepared)
        for group, patterns in (self.spec.joint_groups or {}).items():
            check.joint_patterns(FieldPath(("joint_groups", group)), patterns)
        return [*super()._name_problems(prepared), *check.problems]

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the base's root to the surface the robot stands on."""
        return np.array(self.spec.top_offset, dtype=float)

    @property
    def bottom_offset(self) -> FloatArray:
        """Offset from the base's root to its bottom (default: the root body's MJCF position)."""
        if self.spec.bottom_offset is not None:
            return np.array(self.spec.bottom_offset, dtype=float)
        return np.array(self.source.pristine.body(self.root_name).pos, dtype=float)

    @property
    def horizontal_radius(self) -> float:
        """Footprint radius (metres)."""
        return self.spec.horizontal_radius

    def group_of(self, joint: str) -> str:
        """The body part a base joint (unprefixed name) belongs to."""
        declared = self.spec.joint_groups
        if declared is not None:
            for group, patterns in declared.items():
                if any(matching_joints(p, [joint]) for p in patterns):
                    return group
        return robosuite_group(joint) or self.default_group
