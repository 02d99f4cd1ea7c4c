"""A wheeled mobile base (robosuite's MobileBaseModel), prefix ``mobilebase{idn}_``: the robot's arm
rides on the base's support body."""

from __future__ import annotations

from typing import ClassVar

import mujoco

from assembler.errors import Problem
from assembler.mjcf import compose
from assembler.mjcf.census import Census
from assembler.mjcf.joints import free_joints
from assembler.models.bases.base import RobotBaseModel
from assembler.models.part import FloatArray
from assembler.models.preparation import PreparedPart
from assembler.spec.fieldpath import FieldPath


class MobileBaseModel(RobotBaseModel):
    """A base that moves the whole robot; the arm hangs from its support body."""

    in_registry = False
    prefix_stem = "mobilebase"
    legged: ClassVar[bool] = False
    """A legged base also takes over the robot root's free joint and inertia."""

    def census_contribution(self, robot_root: mujoco.MjsBody) -> Census:
        """Its elements, an outer body that keeps the robot root's name, minus the robot root's free
        joint; a legged base's free joints become the one free joint of that outer body."""
        contribution: Census = super().census_contribution(robot_root)
        contribution["bodies"] += 1
        contribution["joints"] -= free_joints(robot_root.joints)
        base_root = self.prepared_mjspec.worldbody.first_body()
        if self.legged and free_joints(base_root.joints):
            contribution["joints"] += 1 - free_joints(self.prepared_mjspec.joints)
        return contribution

    def carry(
        self, assembly: mujoco.MjSpec, robot: mujoco.MjSpec, robot_prefix: str, offset: FloatArray
    ) -> None:
        """Robot root (its pose) -> this base -> support body -> the robot's former root -> the arm."""
        compose.attach_robot_on_support(
            assembly,
            robot,
            robot_prefix,
            self.part_mjspec(),
            self.naming_prefix,
            self.spec.support_body,
            offset,
            legged=self.legged,
        )

    def complete_alone(self, assembly: mujoco.MjSpec) -> None:
        """Alone, the support carries a stand-in load instead of a robot."""
        compose.add_stand_in_load(assembly, self.naming_prefix + self.spec.support_body)

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        check = self.name_check(prepared)
        check.body(FieldPath(("support_body",)), self.spec.support_body)
        return [*super()._name_problems(prepared), *check.problems]
