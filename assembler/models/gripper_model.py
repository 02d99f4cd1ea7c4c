"""GripperModel: a hand attached at an arm's end-effector body (prefix ``gripper{idn}_``)."""

from __future__ import annotations

import functools
from collections.abc import Sequence
from typing import Any, ClassVar

import mujoco
import numpy as np

from assembler.errors import AssemblerError, MjcfError, Problem
from assembler.mjcf.compose import place_root
from assembler.mjcf.source import MjcfSource, subtree_source
from assembler.models.gripper_actions import ActionMap
from assembler.models.part import FloatArray, PartModel
from assembler.models.preparation import PreparedPart
from assembler.models.registering import REGISTRIES, Registry
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import GripperSpec
from assembler.spec.schema.gripper import ROBOSUITE_SENSORS, ROBOSUITE_SITES

REGISTERED_GRIPPERS: Registry[GripperModel] = REGISTRIES["gripper"]
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
        if spec.actions is not None:
            for number, action in enumerate(spec.actions.dimensions):
                for index, name in enumerate(action.actuators):
                    check.actuator(FieldPath(("actions", "dimensions", number, "actuators", index)), name)
            for name in spec.actions.hold:
                check.actuator(FieldPath(("actions", "hold", name)), name)
        return [*super()._name_problems(prepared), *check.problems]

    def _load_source(self) -> MjcfSource:
        """The gripper's MJCF: the whole file, or the subtree of the spec's ``root_body``."""
        source = super()._load_source()
        if self.spec.root_body is None:
            return source
        try:
            return subtree_source(source, self.spec.root_body)
        except MjcfError as error:
            field = FieldPath(("root_body",))
            raise MjcfError([Problem(p.message, self.locate(field), field) for p in error.problems]) from None

    def own_mjspec(self) -> mujoco.MjSpec:
        """The part's spec (see :meth:`PartModel.own_mjspec`), its root at the origin if the spec
        asks for it (``root_pose: reset``)."""
        mjspec = super().own_mjspec()
        if self.spec.root_pose == "reset":
            place_root(mjspec, (0.0, 0.0, 0.0), (1.0, 0.0, 0.0, 0.0))
        return mjspec

    @property
    def naming_prefix(self) -> str:
        """``gripper{idn}_``; robots pass idn ``"{robot_idn}_{arm}"``, e.g. ``gripper0_right_``."""
        return f"gripper{self.idn}_"

    @property
    def dof(self) -> int:
        """Number of actions the gripper takes: its declared actions', the spec's ``dof``, or its
        number of actuators."""
        if self.spec.actions is not None:
            return len(self.spec.actions.dimensions)
        return self.spec.dof if self.spec.dof is not None else len(self.actuators)

    @functools.cached_property
    def action_map(self) -> ActionMap | None:
        """How actions drive the actuators, from the spec's ``actions``; None when it declares none."""
        if self.spec.actions is None:
            return None
        names = [actuator.name for actuator in self.prepared_mjspec.actuators]
        return ActionMap.of(self.spec.actions, names, self.spec.speed)

    def format_action(self, action: Sequence[float]) -> FloatArray:
        """One output in [-1, 1] per actuator (in MJCF order) for a policy's ``action`` (``dof``
        values), moving ``current_action`` as robosuite's grippers do."""
        action_map = self.action_map
        if action_map is None:
            raise AssemblerError(
                f"{self.describe()} declares no actions: add an 'actions:' block saying which actuators "
                "each action drives and in which direction"
            )
        outputs, self.current_action = action_map.format_action(action, self.current_action)
        return outputs

    @property
    def speed(self) -> float:
        """Per-step increment of an action."""
        return self.spec.speed

    @property
    def important_sites(self) -> dict[str, str]:
        """Role -> prefixed site name: robosuite's roles whose sites the MJCF has, then the spec's."""
        present = {r: n for r, n in ROBOSUITE_SITES.items() if self.prepared_mjspec.site(n) is not None}
        return {
            role: self.naming_prefix + name for role, name in {**present, **self.spec.important_sites}.items()
        }

    @property
    def important_geoms(self) -> dict[str, list[str]]:
        """Role -> prefixed geom names."""
        return {role: self.prefixed(list(names)) for role, names in self.spec.important_geoms.items()}

    @property
    def important_sensors(self) -> dict[str, str]:
        """Role -> prefixed sensor name: robosuite's roles whose sensors the MJCF has, then the spec's."""
        present = {r: n for r, n in ROBOSUITE_SENSORS.items() if self.prepared_mjspec.sensor(n) is not None}
        return {
            role: self.naming_prefix + name
            for role, name in {**present, **self.spec.important_sensors}.items()
        }

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
