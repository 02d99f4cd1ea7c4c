"""robosuite gripper and base classes made from our gripper and base specs.

Each is a subclass of robosuite's own model class for its kind (``GripperModel``; ``MountModel``,
``MobileBaseModel``, ``LegBaseModel`` or ``NullBaseModel`` by the base's type: robosuite dispatches
on them with ``isinstance``) reading the lossless file of our part, so robosuite's XML layer holds
exactly our part, and robosuite's own tools (``GripperTester``, its ``add_*`` merges) work on it.
The semantics robosuite asks of a gripper come from its spec: ``dof`` and ``format_action`` from
``actions``, ``speed``, ``init_qpos``, the important sites, geoms and sensors.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any, ClassVar

import numpy as np
from robosuite.models.bases import LegBaseModel, MobileBaseModel, MountModel, NullBaseModel
from robosuite.models.grippers import GripperModel as RobosuiteGripper

from assembler.errors import SpecError
from assembler.models import GripperModel, PartModel, RobotBaseModel
from assembler.models.part import FloatArray
from assembler.robosuite.parts import part_file, robosuite_part
from assembler.spec.fieldpath import FieldPath

BASE_CLASSES: dict[str, type] = {
    "mount": MountModel,
    "mobile": MobileBaseModel,
    "legged": LegBaseModel,
    "null": NullBaseModel,
}
"""robosuite's model class per base type."""

ACTIONS = FieldPath(("actions",))

_classes: dict[type, type] = {}
"""The robosuite class made of each spec class."""

_recorded: dict[tuple[str, str], type] = {}
"""The robosuite class made of each (family, name) installed from its registration record."""


class SpecGripper(RobosuiteGripper):  # type: ignore[misc]
    """A gripper spec as a robosuite gripper model (subclassed once per spec)."""

    assembler_class: ClassVar[type[GripperModel] | None] = None
    """The assembler's class for the spec."""

    current_action: FloatArray
    """The gripper's last outputs (robosuite's state, zeroed at each reset)."""

    def __init__(self, idn: int | str = 0) -> None:
        assert self.assembler_class is not None, "made per spec by robosuite_class_of"
        self.part: GripperModel = robosuite_part(self.assembler_class, idn)
        """Our gripper: its spec, actions and state."""
        if self.part.action_map is None and self.part.actuators:
            actuators = ", ".join(name[len(self.part.naming_prefix) :] for name in self.part.actuators)
            message = (
                f"the gripper has actuators ({actuators}) but no 'actions:' saying how a policy's "
                "actions drive "
                "them; robosuite needs one (see docs/robosuite.md, Gripper actions)"
            )
            raise SpecError(self.part.spec_problem(ACTIONS, message))
        super().__init__(part_file(self.part), idn=idn)

    @property
    def dof(self) -> int:
        """Number of action values the gripper takes."""
        return self.part.dof

    @property
    def speed(self) -> float:
        """How far one action moves an output."""
        return self.part.speed

    @property
    def init_qpos(self) -> FloatArray:
        """The spec's open pose; without one, every joint at zero (MuJoCo's own ``qpos0`` for joints
        without a ``ref``), as robosuite's reset writes one value per gripper joint."""
        values = self.part.spec.init_qpos
        return np.zeros(len(self.joints)) if values is None else np.array(values, dtype=float)

    def format_action(self, action: Sequence[float]) -> FloatArray:
        """One output in [-1, 1] per actuator; ``current_action`` is the state robosuite resets."""
        if self.part.action_map is None:
            return np.asarray(action, dtype=float)  # no actuators: robosuite's null gripper
        self.part.current_action = np.asarray(self.current_action, dtype=np.float64)
        outputs = self.part.format_action(action)
        self.current_action = self.part.current_action
        return outputs

    @property
    def _important_sites(self) -> dict[str, str]:
        return {**super()._important_sites, **self.part.spec.important_sites}

    @property
    def _important_geoms(self) -> dict[str, list[str]]:
        return {**super()._important_geoms, **{k: list(v) for k, v in self.part.spec.important_geoms.items()}}

    @property
    def _important_sensors(self) -> dict[str, str]:
        return {**super()._important_sensors, **self.part.spec.important_sensors}


class SpecBase:
    """What every base spec's robosuite class adds to robosuite's class for its type."""

    assembler_class: ClassVar[type[RobotBaseModel] | None] = None
    """The assembler's class for the spec."""

    def __init__(self, idn: int | str = 0) -> None:
        assert self.assembler_class is not None, "made per spec by robosuite_class_of"
        self.part: RobotBaseModel = robosuite_part(self.assembler_class, idn)
        """Our base."""
        super().__init__(part_file(self.part), idn=idn)  # type: ignore[call-arg]

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the base's root to the surface the robot stands on."""
        return self.part.top_offset

    @property
    def bottom_offset(self) -> FloatArray:
        """Offset from the base's root to its bottom."""
        return self.part.bottom_offset

    @property
    def horizontal_radius(self) -> float:
        """Footprint radius (metres)."""
        return self.part.horizontal_radius

    @property
    def init_qpos(self) -> FloatArray:
        """The legs' initial positions (robosuite's LeggedRobot reads them from a legged base)."""
        return np.array(self.part.spec.init_qpos or [], dtype=float)


def robosuite_class_of(spec_class: type[PartModel]) -> type:
    """The robosuite class of a gripper or base spec class (made once, not yet in robosuite's registries)."""
    made = _classes.get(spec_class)
    if made is not None:
        return made
    if issubclass(spec_class, GripperModel):
        family, base_type = "gripper", ""
    elif issubclass(spec_class, RobotBaseModel):
        family, base_type = "base", spec_class.spec.type
    else:
        raise TypeError(f"robosuite_class_of: {spec_class.__name__} is neither a gripper nor a base")
    recorded = _recorded.get((family, spec_class.__name__))
    if recorded is not None and getattr(recorded, "assembler_class", None) is spec_class:
        made = recorded  # installed from its registration record
    else:
        made = _made(spec_class.__name__, base_type, spec_class)
    _classes[spec_class] = made
    return made


def recorded_class(family: str, name: str, base_type: str, assembler_class: object) -> type:
    """The robosuite class of a gripper or base known by its registration record (made once per
    name): ``assembler_class`` stands for the spec class until it is read."""
    made = _recorded.get((family, name))
    if made is None:
        made = _recorded[(family, name)] = _made(name, base_type, assembler_class)
    return made


def _made(name: str, base_type: str, assembler_class: object) -> type:
    """robosuite's class for the gripper (``base_type`` empty) or base ``name``."""
    namespace: dict[str, Any] = {
        "assembler_class": assembler_class,
        "__module__": __name__,
        "__doc__": f"{name} from its spec, for robosuite's environments.",
    }
    bases = (SpecBase, BASE_CLASSES[base_type]) if base_type else (SpecGripper,)
    return type(name, bases, namespace)
