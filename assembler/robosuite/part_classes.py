"""robosuite gripper and base classes made from our gripper and base specs.

Each is a subclass of robosuite's own model class for its kind (``GripperModel``; ``MountModel``,
``MobileBaseModel``, ``LegBaseModel`` or ``NullBaseModel`` by the base's type: robosuite dispatches
on them with ``isinstance``) reading the lossless file of our part, so robosuite's XML layer holds
exactly our part, and robosuite's own tools (``GripperTester``, its ``add_*`` merges) work on it.
The semantics robosuite asks of a gripper come from its spec: ``dof`` and ``format_action`` from
``actions``, ``speed``, ``init_qpos``, the important sites, geoms and sensors.
"""

from __future__ import annotations

import dataclasses
import inspect
from collections.abc import Callable, Sequence
from typing import Any, ClassVar, TypeVar

import numpy as np
from robosuite.models.bases import LegBaseModel, MobileBaseModel, MountModel, NullBaseModel
from robosuite.models.grippers import GripperModel as RobosuiteGripper

from assembler import models
from assembler.errors import SpecError
from assembler.models.gripper_actions import ActionMap, FloatArray
from assembler.robosuite.files import file_key, recorded_part_file
from assembler.robosuite.make_records import (
    Facts,
    Origins,
    origins_of,
    recorded_facts,
    spec_class_of,
    spec_file,
)
from assembler.spec.fieldpath import FieldPath

P = TypeVar("P", bound="models.PartModel")

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

    assembler_class: ClassVar[type[models.GripperModel] | None] = None
    """The assembler's class for the spec."""

    current_action: FloatArray
    """The gripper's last outputs (robosuite's state, zeroed at each reset)."""

    _part_idn: int | str
    """The idn our part is made with."""

    _facts: Facts | None
    """What robosuite reads of the spec, from its make record (None: read from the spec)."""

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(_robosuite_file(self, "gripper", idn), idn=idn)

    @property
    def part(self) -> models.GripperModel:
        """Our gripper: its spec, actions and state (made on first use when the make record answered
        what robosuite reads)."""
        made: models.GripperModel | None = self.__dict__.get("_part")
        if made is None:
            made = _our_part(spec_class_of(type(self)), self._part_idn)
            if made.action_map is None and made.actuators:
                actuators = ", ".join(name[len(made.naming_prefix) :] for name in made.actuators)
                message = (
                    f"the gripper has actuators ({actuators}) but no 'actions:' saying how a policy's "
                    "actions drive "
                    "them; robosuite needs one (see docs/robosuite.md, Gripper actions)"
                )
                raise SpecError(made.spec_problem(ACTIONS, message))
            self.__dict__["_part"] = made
        return made

    def _spec_facts(self) -> tuple[Facts, Origins]:
        """What robosuite reads of the spec (the part made now), with the files it depends on."""
        part = self.part
        spec: Any = part.spec
        inputs = part.part_inputs()
        actions = part.action_map
        facts = {
            "file": file_key(inputs) if inputs.spec_made else "",
            "dof": part.dof,
            "speed": part.speed,
            "init_qpos": spec.init_qpos,
            "important_sites": dict(spec.important_sites),
            "important_geoms": {role: list(names) for role, names in spec.important_geoms.items()},
            "important_sensors": dict(spec.important_sensors),
            "actions": None
            if actions is None
            else {field.name: _plain(getattr(actions, field.name)) for field in dataclasses.fields(actions)},
        }
        return facts, origins_of([part])

    def _of_spec(self, name: str, read: Callable[[models.GripperModel], Any]) -> Any:
        """A value robosuite reads of the gripper: the make record's, else ``read`` of our part."""
        return self._facts[name] if self._facts is not None else read(self.part)

    @property
    def dof(self) -> int:
        """Number of action values the gripper takes."""
        return int(self._of_spec("dof", lambda part: part.dof))

    @property
    def speed(self) -> float:
        """How far one action moves an output."""
        return float(self._of_spec("speed", lambda part: part.speed))

    @property
    def init_qpos(self) -> FloatArray:
        """The spec's open pose; without one, every joint at zero (MuJoCo's own ``qpos0`` for joints
        without a ``ref``), as robosuite's reset writes one value per gripper joint."""
        values = self._of_spec("init_qpos", lambda part: part.spec.init_qpos)
        return np.zeros(len(self.joints)) if values is None else np.array(values, dtype=float)

    def format_action(self, action: Sequence[float]) -> FloatArray:
        """One output in [-1, 1] per actuator; ``current_action`` is the state robosuite resets."""
        if self._facts is not None and "_part" not in self.__dict__:
            recorded = self._facts["actions"]
            if recorded is None:
                return np.asarray(action, dtype=float)  # no actuators: robosuite's null gripper
            actions = self.__dict__.get("_actions")
            if actions is None:
                actions = self.__dict__["_actions"] = ActionMap(**_arrays(recorded))
            outputs, self.current_action = actions.format_action(
                action, np.asarray(self.current_action, dtype=np.float64)
            )
            return outputs
        if self.part.action_map is None:
            return np.asarray(action, dtype=float)  # no actuators: robosuite's null gripper
        self.part.current_action = np.asarray(self.current_action, dtype=np.float64)
        outputs = self.part.format_action(action)
        self.current_action = self.part.current_action
        return outputs

    @property
    def _important_sites(self) -> dict[str, str]:
        return {
            **super()._important_sites,
            **self._of_spec("important_sites", lambda p: p.spec.important_sites),
        }

    @property
    def _important_geoms(self) -> dict[str, list[str]]:
        geoms = self._of_spec("important_geoms", lambda part: part.spec.important_geoms)
        return {**super()._important_geoms, **{k: list(v) for k, v in geoms.items()}}

    @property
    def _important_sensors(self) -> dict[str, str]:
        return {
            **super()._important_sensors,
            **self._of_spec("important_sensors", lambda part: part.spec.important_sensors),
        }


def _robosuite_file(made: SpecGripper | SpecBase, family: str, idn: int | str) -> str:
    """The file robosuite's class of a gripper or base is made from: its kept part file, named by
    its make record (our part not made), else our part's file (the part made now); sets the
    object's ``_facts`` (None when the class keeps no make record)."""
    assert inspect.getattr_static(type(made), "assembler_class", None) is not None, "made per spec"
    made._part_idn = idn
    made._facts = None
    file = spec_file(type(made))
    if file is not None:
        material = {"family": family, "name": type(made).__name__, "file": file, "idn": str(idn), "added": []}
        made._facts = recorded_facts(material, made._spec_facts)
        if made._facts["file"]:
            return recorded_part_file(made._facts["file"], lambda: made.part)
    from assembler.robosuite import parts  # a class without a make record makes its part now

    return parts.part_file(made.part)


def _our_part(spec_class: type[P], idn: int | str) -> P:
    """Our part for robosuite, made on first use: a make answered by its record makes none."""
    from assembler.robosuite import parts

    return parts.robosuite_part(spec_class, idn)


def _plain(value: Any) -> Any:
    """A value of an action map as JSON holds it (arrays as lists)."""
    return value.tolist() if isinstance(value, np.ndarray) else value


def _arrays(recorded: dict[str, Any]) -> dict[str, Any]:
    """An action map's fields from its record (its arrays as the map makes them)."""
    return {
        **recorded,
        "source": np.array(recorded["source"], dtype=np.int64),
        "sign": np.array(recorded["sign"], dtype=float),
        "held": np.array(recorded["held"], dtype=float),
    }


class SpecBase:
    """What every base spec's robosuite class adds to robosuite's class for its type."""

    assembler_class: ClassVar[type[models.RobotBaseModel] | None] = None
    """The assembler's class for the spec."""

    _part_idn: int | str
    """The idn our part is made with."""

    _facts: Facts | None
    """What robosuite reads of the spec, from its make record (None: read from the spec)."""

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(_robosuite_file(self, "base", idn), idn=idn)  # type: ignore[call-arg]

    @property
    def part(self) -> models.RobotBaseModel:
        """Our base (made on first use when the make record answered what robosuite reads)."""
        made: models.RobotBaseModel | None = self.__dict__.get("_part")
        if made is None:
            made = self.__dict__["_part"] = _our_part(spec_class_of(type(self)), self._part_idn)
        return made

    def _spec_facts(self) -> tuple[Facts, Origins]:
        """What robosuite reads of the spec (the part made now), with the files it depends on."""
        part = self.part
        inputs = part.part_inputs()
        facts = {
            "file": file_key(inputs) if inputs.spec_made else "",
            "top_offset": part.top_offset.tolist(),
            "bottom_offset": part.bottom_offset.tolist(),
            "horizontal_radius": float(part.horizontal_radius),
            "init_qpos": part.spec.init_qpos,
        }
        return facts, origins_of([part])

    def _of_spec(self, name: str, read: Callable[[models.RobotBaseModel], Any]) -> Any:
        """A value robosuite reads of the base: the make record's, else ``read`` of our part."""
        return self._facts[name] if self._facts is not None else read(self.part)

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the base's root to the surface the robot stands on."""
        return np.array(self._of_spec("top_offset", lambda part: part.top_offset), dtype=float)

    @property
    def bottom_offset(self) -> FloatArray:
        """Offset from the base's root to its bottom."""
        return np.array(self._of_spec("bottom_offset", lambda part: part.bottom_offset), dtype=float)

    @property
    def horizontal_radius(self) -> float:
        """Footprint radius (metres)."""
        return float(self._of_spec("horizontal_radius", lambda part: part.horizontal_radius))

    @property
    def init_qpos(self) -> FloatArray:
        """The legs' initial positions (robosuite's LeggedRobot reads them from a legged base)."""
        return np.array(self._of_spec("init_qpos", lambda part: part.spec.init_qpos) or [], dtype=float)


def robosuite_class_of(spec_class: type[models.PartModel]) -> type:
    """The robosuite class of a gripper or base spec class (made once, not yet in robosuite's registries)."""
    made = _classes.get(spec_class)
    if made is not None:
        return made
    if issubclass(spec_class, models.GripperModel):
        family, base_type = "gripper", ""
    elif issubclass(spec_class, models.RobotBaseModel):
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
