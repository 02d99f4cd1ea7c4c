"""ManipulatorModel: a robot with one (right) or two (right, left) arms ending in end-effector bodies."""

from __future__ import annotations

from assembler.models.robot_model import RobotModel


class ManipulatorModel(RobotModel):
    """A robot arm or arms; grippers attach at the end-effector bodies."""

    abstract = True
