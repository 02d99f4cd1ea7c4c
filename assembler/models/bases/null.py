"""A null base (robosuite's NullBaseModel), prefix ``nullbase{idn}_``: only its sites, in the world frame."""

from __future__ import annotations

from collections import Counter

import mujoco

from assembler.mjcf import compose
from assembler.mjcf.census import Census
from assembler.models.bases.base import RobotBaseModel
from assembler.models.part import FloatArray


class NullBaseModel(RobotBaseModel):
    """No base: the robot stands at the world origin; the base contributes its sites."""

    in_registry = False
    prefix_stem = "nullbase"

    def census_contribution(self, robot_root: mujoco.MjsBody) -> Census:
        """Its sites only."""
        return Counter({"sites": len(self.prepared_mjspec.sites)})

    def carry(
        self, assembly: mujoco.MjSpec, robot: mujoco.MjSpec, robot_prefix: str, offset: FloatArray
    ) -> None:
        """The robot at the world origin, this base's sites in the world (robosuite's add_null_base)."""
        compose.attach_at_world(assembly, robot, robot_prefix)
        compose.add_sites_at_world(assembly, self.part_mjspec(), self.naming_prefix)
