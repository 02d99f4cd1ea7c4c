"""GripperModel: a hand attached at an arm's end-effector body (prefix ``gripper{idn}_``)."""

from __future__ import annotations

from typing import ClassVar

import numpy as np

from assembler.errors import MjcfError, Problem, summarize_names
from assembler.models.part import FloatArray, PartModel
from assembler.schema import GripperSpec


class GripperModel(PartModel):
    """A gripper built from its spec; important sites, geoms and sensors are checked to exist."""

    abstract = True
    family: ClassVar[str] = "gripper"
    spec: ClassVar[GripperSpec]
    collision_rgba = (0.0, 0.0, 0.5, 1.0)  # robosuite's GRIPPER_COLLISION_COLOR

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self._check_important_names()
        self.current_action = np.zeros(self.dof)

    def _check_important_names(self) -> None:
        spec = self.spec
        present = {
            "important_sites": {s.name for s in self.prepared.sites},
            "important_geoms": {g.name for g in self.prepared.geoms},
            "important_sensors": {s.name for s in self.prepared.sensors},
        }
        problems: list[Problem] = []

        def check(field: str, role: str, name: str) -> None:
            if name not in present[field]:
                known = summarize_names(sorted(n for n in present[field] if n))
                problems.append(
                    self.spec_problem((field, role), f"'{name}' does not exist in the MJCF. Known: {known}")
                )

        for role, name in spec.important_sites.items():
            check("important_sites", role, name)
        for role, names in spec.important_geoms.items():
            for name in names:
                check("important_geoms", role, name)
        for role, name in spec.important_sensors.items():
            check("important_sensors", role, name)
        if self.prepared.body(spec.eef_body) is None:
            problems.append(self.spec_problem(("eef_body",), f"no body named '{spec.eef_body}' in the MJCF"))
        if problems:
            raise MjcfError(problems)

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
