"""A fixed mount (robosuite's MountModel), prefix ``fixed_mount{idn}_``: merged under the robot's root."""

from __future__ import annotations

import mujoco

from assembler.mjcf import compose
from assembler.models.bases.base import RobotBaseModel
from assembler.models.part import FloatArray


class MountModel(RobotBaseModel):
    """A pedestal or stand: the robot's root stays where it is, the mount hangs below it."""

    in_registry = False
    prefix_stem = "fixed_mount"

    def carry(
        self, assembly: mujoco.MjSpec, robot: mujoco.MjSpec, robot_prefix: str, offset: FloatArray
    ) -> None:
        """The robot at the world origin; the mount becomes the last child of the robot's root."""
        root = robot_prefix + robot.worldbody.first_body().name
        compose.attach_at_world(assembly, robot, robot_prefix)
        compose.attach_mount(assembly, root, self.part_mjspec(), self.naming_prefix, offset)
