"""GripperModel: a hand attached at an arm's end-effector body (prefix ``gripper{idn}_``)."""

from __future__ import annotations

from typing import Any, ClassVar

import numpy as np

from assembler.errors import Problem
from assembler.fieldpath import FieldPath
from assembler.models.part import FloatArray, PartModel
from assembler.models.preparation import PreparedPart
from assembler.models.registering import Registry
from assembler.schema import GripperSpec

REGISTERED_GRIPPERS: Registry[GripperModel] = Registry("gripper")
"""Every registered gripper class by name."""


class GripperModel(PartModel):
    """A gripper built from its spec; important sites, geoms and sensors are checked to exist."""

    in_registry = False
    family: ClassVar[str] = "gripper"
    registry: ClassVar[Registry[Any]] = REGISTERED_GRIPPERS
    spec: ClassVar[GripperSpec]
    collision_rgba = (0.0, 0.0, 0.5, 1.0)  # robosuite's GRIPPER_COLLISION_COLOR

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self._current_action: FloatArray | None = None

    @property
    def current_action(self) -> FloatArray:
        """The gripper's last action, one value per action dimension (zeros at first)."""
        if self._current_action is None:
            self._current_action = np.zeros(self.dof)
        return self._current_action

    @current_action.setter
    def current_action(self, value: FloatArray) -> None:
        self._current_action = np.asarray(value, dtype=float)

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        spec = self.spec
        check = self.name_check(prepared)
        for role, name in spec.important_sites.items():
            check.site(FieldPath(("important_sites", role)), name)
        for role, names in spec.important_geoms.items():
            for index, name in enumerate(names):
                check.geom(FieldPath(("important_geoms", role, index)), name)
        for role, name in spec.important_sensors.items():
            check.sensor(FieldPath(("important_sensors", role)), name)
        check.body(FieldPath(("eef_body",)), spec.eef_body)
        return [*super()._name_problems(prepared), *check.problems]

    @property
    def naming_prefix(self) -> str:
        """``gripper{idn}_``; robots pass idn ``"{robot_idn}_{arm}"``, e.g. ``gripper0_right_``."""
        return f"gripper{self.idn}_"

    @property
    def dof(self) -> int:
        """Number of actions the gripper takes (the spec's, or its number of actuators)."""
        return self.spec.dof if self.spec.dof is not None else len(self.actuators)

    @property
    def speed(self) -> float:
        """Per-step increment of an action."""
        return self.spec.speed

    @property
    def important_sites(self) -> dict[str, str]:
        """Role -> prefixed site name."""
        return {role: self.naming_prefix + name for role, name in self.spec.important_sites.items()}

    @property
    def important_geoms(self) -> dict[str, list[str]]:
        """Role -> prefixed geom names."""
        return {role: self.prefixed(list(names)) for role, names in self.spec.important_geoms.items()}

    @property
    def important_sensors(self) -> dict[str, str]:
        """Role -> prefixed sensor name."""
        return {role: self.naming_prefix + name for role, name in self.spec.important_sensors.items()}

    @property
    def eef_body(self) -> str:
        """The gripper's grip-point body (prefixed)."""
        return self.naming_prefix + self.spec.eef_body

    @property
    def bottom_offset(self) -> FloatArray:
        """Zero, as in robosuite."""
        return np.zeros(3)

    @property
    def top_offset(self) -> FloatArray:
        """Zero, as in robosuite."""
        return np.zeros(3)

    @property
    def horizontal_radius(self) -> float:
        """Zero, as in robosuite."""
        return 0.0
