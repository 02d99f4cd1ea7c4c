"""RobotBaseModel: what a robot stands on — a fixed mount, a mobile base, a legged base, or nothing."""

from __future__ import annotations

from typing import ClassVar

import mujoco
import numpy as np

from assembler.mjcf import compose
from assembler.models.groups import robosuite_group
from assembler.models.joint_rules import matching_joints
from assembler.models.part import FloatArray, PartModel
from assembler.schema import BaseSpec

PREFIXES: dict[str, str] = {
    "mount": "fixed_mount",
    "mobile": "mobilebase",
    "legged": "leg",
    "null": "nullbase",
}
"""robosuite's prefix per base kind, e.g. ``mobilebase0_``."""


class RobotBaseModel(PartModel):
    """A base built from its spec; the robot's ``add_base`` merges it by its ``type``."""

    abstract = True
    family: ClassVar[str] = "base"
    spec: ClassVar[BaseSpec]
    collision_rgba = (0.5, 0.5, 0.0, 1.0)  # robosuite's MOUNT_COLLISION_COLOR

    @property
    def type(self) -> str:
        """mount, mobile, legged or null."""
        return self.spec.type

    @property
    def naming_prefix(self) -> str:
        """``fixed_mount{idn}_``, ``mobilebase{idn}_``, ``leg{idn}_`` or ``nullbase{idn}_``."""
        return f"{PREFIXES[self.spec.type]}{self.idn}_"

    def _complete_alone(self, assembly: mujoco.MjSpec) -> None:
        # A mobile or legged base carries the robot on its support body; alone, it gets a stand-in.
        if self.spec.type in ("mobile", "legged"):
            compose.add_stand_in_load(assembly, self.naming_prefix + self.spec.support_body)

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
                if any(joint in matching_joints(p, [joint]) for p in patterns):
                    return group
        by_name = robosuite_group(joint)
        if by_name is not None:
            return by_name
        return "legs" if self.spec.type == "legged" else "base"
