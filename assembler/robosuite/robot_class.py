"""robosuite robot classes made from our robot specs.

A :class:`SpecRobot` is one of robosuite's ``ManipulatorModel``s, so environments, controllers and
robosuite's tests treat it as theirs. What reaches the simulator is our assembly, not robosuite's XML
surgery: ``add_base`` and ``add_gripper`` hand the parts to the assembler, and ``set_mujoco_model``
(the last step of robosuite's ``Robot.load_model``) replaces the XML tree by the lossless text of our
assembly of robot, base and grippers. The name lists robosuite reads (joints, actuators, geoms,
sites) come from robosuite's own parse of each part's lossless file, so they are the robot's own,
and every name in them exists in that assembly.

One class per robot is offered to robosuite: the :class:`SpecRobot` subclass :func:`robot_class`
makes, in ``REGISTERED_ROBOTS``. robosuite's other table, ``ROBOT_CLASS_MAPPING``, gets robosuite's
own Robot type for the robot (``FixedBaseRobot``, ``LeggedRobot``, ...; no class of ours). Our spec
class (``assembler.models``' registry) is not given to robosuite, and it cannot be this class:
``REGISTERED_ROBOTS[name](idn=...)`` must make one of robosuite's ``ManipulatorModel``s (an XML tree
with ``_elements``, which robosuite's ``create_composite_robot`` subclasses by name), and the two
hierarchies give 45 names different meanings (``get_model``, ``models``, ``joints``, ``init_qpos``,
``add_gripper``, ``set_joint_attribute``, ...). So a :class:`SpecRobot` holds our robot as an
instance (``assembly``, made for robosuite by :func:`~assembler.robosuite.parts.robosuite_part`:
no class of its own). Grippers and bases likewise (:mod:`assembler.robosuite.part_classes`).
"""

from __future__ import annotations

import inspect
import warnings
from collections.abc import Callable, Sequence
from typing import Any, ClassVar, TypeVar

import mujoco
import numpy as np
from numpy.typing import NDArray
from robosuite.models.base import MujocoXML
from robosuite.models.bases import RobotBaseModel as RobosuiteBase
from robosuite.models.grippers import GripperModel as RobosuiteGripper
from robosuite.models.robots.manipulators.manipulator_model import ManipulatorModel as RobosuiteManipulator
from robosuite.models.robots.robot_model import RobotModelMeta

from assembler import models
from assembler.errors import AssemblerError, AssemblerWarning, SpecError
from assembler.models.registering import REGISTRIES, Registry
from assembler.robosuite.conventions import base_in_robosuite
from assembler.robosuite.files import file_key, recorded_assembly_file, recorded_part_file
from assembler.robosuite.make_records import (
    Facts,
    Origins,
    origins_of,
    recorded_facts,
    spec_class_of,
    spec_file,
)
from assembler.robosuite.placement import arena_offsets, in_robosuites_shape, offsets
from assembler.robosuite.same_names import check_same_names
from assembler.spec.expressions import ExpressionError
from assembler.spec.fieldpath import FieldPath

P = TypeVar("P", bound="models.PartModel")
FloatArray = NDArray[np.float64]

GROUPS = ("arm", "base", "torso", "head", "legs")
"""robosuite's joint and actuator groups (our parts name the arms' ``arm_joints``)."""

_WITHOUT_INIT_QPOS: set[str] = set()
"""Robots whose missing ``init_qpos`` was said (once per robot and process)."""


class QuietMeta(RobotModelMeta):  # type: ignore[misc]
    """robosuite's robot metaclass, except for our classes: robosuite's registers every class it makes
    by name at once, silently replacing another of that name; ours are registered by
    :mod:`assembler.robosuite.registries`, which refuses conflicts. Classes others derive from ours
    (robosuite's ``create_composite_robot``) register as robosuite's own do."""

    def __new__(mcls, name: str, bases: tuple[type, ...], namespace: dict[str, Any]) -> QuietMeta:
        if "assembler_class" in namespace:
            return type.__new__(mcls, name, bases, namespace)
        return super().__new__(mcls, name, bases, namespace)  # type: ignore[no-any-return]


class SpecRobot(RobosuiteManipulator, metaclass=QuietMeta):  # type: ignore[misc]
    """A robot spec as a robosuite robot model (subclassed once per spec by :func:`robot_class`)."""

    assembler_class: ClassVar[type[models.ManipulatorModel] | None] = None
    """The assembler's class for the spec."""

    arms: ClassVar[list[str]] = []
    """The arms, right first (robosuite reads them from the class)."""

    base: Any
    """robosuite's base object the robot stands on (None until ``add_base``)."""

    def __init__(self, idn: int | str = 0) -> None:
        if inspect.getattr_static(type(self), "assembler_class", None) is None:
            raise AssemblerError("SpecRobot is made per spec: use assembler.robosuite.robot_class(name)")
        self._robot_idn = idn
        self._added: list[tuple[Any, str | None]] = []
        """robosuite's base, then grippers with the arm names they were added for, in order: what
        our assembly is given when it is made (at once, or on first use when recorded)."""
        self._facts: Facts | None = None
        """What robosuite reads of the spec, from its make record (None: read from the spec, for a
        class not made from a shipped spec file, or with the cache off: it has no record kept)."""
        self._file = spec_file(type(self))
        if self._file is not None:
            self._facts = recorded_facts(self._material(), self._spec_facts)
            if self._facts["file"]:
                super().__init__(recorded_part_file(self._facts["file"], lambda: self.assembly), idn=idn)
                return
        from assembler.robosuite import parts  # a class without a make record makes its part now

        super().__init__(parts.part_file(self.assembly), idn=idn)

    @property
    def assembly(self) -> models.ManipulatorModel:
        """Our robot, base and grippers, built the assembler's way (made on first use when the make
        record answered what robosuite reads)."""
        made: models.ManipulatorModel | None = self.__dict__.get("_assembly")
        if made is None:
            # made on first use: a make answered by its record makes none
            from assembler.robosuite import parts

            spec_class = spec_class_of(type(self))
            made = self.__dict__["_assembly"] = parts.robosuite_part(spec_class, self._robot_idn)
            for part, arm_name in self._added:
                self._give(made, part, arm_name)
        return made

    # ----- the make record --------------------------------------------------------------------

    def _material(self, *added: tuple[Any, str | None]) -> dict[str, Any]:
        """What a make record of this robot (with ``added``) is keyed by, besides the environment."""
        return {
            "family": "robot",
            "name": type(self).__name__,
            "file": self._file,
            "idn": str(self._robot_idn),
            "added": [[type(part).__name__, str(part.idn), arm] for part, arm in added],
        }

    def _spec_facts(self) -> tuple[Facts, Origins]:
        """What robosuite reads of the spec (the part made now), with the files it depends on."""
        robot = self.assembly
        spec: Any = robot.spec
        inputs = robot.part_inputs()
        facts = {
            "file": file_key(inputs) if inputs.spec_made else "",
            "name": str(spec.name),
            "arm_type": str(spec.arm_type),
            "eef_name": {arm: spec.eef_body(arm) for arm in self.arms},
            "default_base": str(base_in_robosuite(spec)),
            "default_gripper": {arm: spec.default_grippers.get(arm) for arm in self.arms},
            "default_controller_config": dict(spec.default_controller_config),
            "init_qpos_declared": spec.init_qpos is not None,
            "describe": robot.describe(),
            "init_base_qpos": spec.robosuite.init_base_qpos,
            "init_torso_qpos": spec.robosuite.init_torso_qpos,
            "arenas": arena_offsets(spec),
            "top_offset": list(spec.top_offset),
            "horizontal_radius": float(spec.horizontal_radius),
        }
        return facts, origins_of([robot])

    def _assembled_facts(self) -> tuple[Facts, Origins]:
        """What robosuite reads of the assembly as it stands (joints and actuators by group, the
        initial pose, the key of its file), with the files it depends on."""
        robot = self.assembly
        inputs = robot.build_inputs()
        facts = {
            "file": file_key(inputs) if inputs.cacheable else "",
            "init_qpos": robot.init_qpos.tolist(),
            **{f"{group}_joints": list(getattr(robot, f"{group}_joints")) for group in GROUPS},
            **{f"{group}_actuators": list(getattr(robot, f"{group}_actuators")) for group in GROUPS},
        }
        return facts, origins_of([robot, *robot.models])

    def _recorded(self) -> Facts | None:
        """The make record of the assembly as it stands, when robosuite's values come from records
        (made now, and recorded, if the assembly has none)."""
        if self._facts is None:
            return None
        return recorded_facts(self._material(*self._added), self._assembled_facts)

    def _fact(self, name: str) -> Any:
        assert self._facts is not None
        return self._facts[name]

    def _of_spec(self, name: str, read: Callable[[Any], Any]) -> Any:
        """A value robosuite reads of the spec: the make record's, else ``read`` of the spec."""
        return self._facts[name] if self._facts is not None else read(self.spec)

    # ----- what robosuite reads from the spec ---------------------------------------------

    @property
    def spec(self) -> Any:
        """The robot's validated spec."""
        return self.assembly.spec

    @property
    def arm_type(self) -> str:
        """single or bimanual."""
        return str(self._of_spec("arm_type", lambda spec: spec.arm_type))

    @property
    def _eef_name(self) -> dict[str, str]:
        if self._facts is not None:
            return dict(self._fact("eef_name"))
        return {arm: self.spec.eef_body(arm) for arm in self.arms}

    @property
    def default_base(self) -> str:
        """The spec's base, or its ``robosuite.stand_in_base`` (robosuite cannot build a robot without)."""
        return str(self._of_spec("default_base", base_in_robosuite))

    @property
    def default_gripper(self) -> dict[str, str | None]:
        """Per arm, the spec's gripper (None: robosuite's null gripper)."""
        if self._facts is not None:
            return dict(self._fact("default_gripper"))
        return {arm: self.spec.default_grippers.get(arm) for arm in self.arms}

    @property
    def default_controller_config(self) -> dict[str, str]:
        """Controller config name per body part (robosuite's fallback for parts its config lacks)."""
        return dict(self._of_spec("default_controller_config", lambda spec: spec.default_controller_config))

    @property
    def init_qpos(self) -> FloatArray:
        """The spec's initial joint positions; without them, the model file's ``qpos0`` (each joint's
        ``ref``, zero unless the file says otherwise), said once per robot: robosuite resets to it."""
        recorded = self._recorded()
        values = np.array(recorded["init_qpos"], dtype=float) if recorded else self.assembly.init_qpos
        declared = self._fact("init_qpos_declared") if recorded else self.spec.init_qpos is not None
        name = self._fact("name") if recorded else self.spec.name
        if not declared and name not in _WITHOUT_INIT_QPOS:
            _WITHOUT_INIT_QPOS.add(name)
            described = self._fact("describe") if recorded else self.assembly.describe()
            warnings.warn(
                f"{described} has no init_qpos: robosuite resets its joints to the model "
                f"file's qpos0 {list(values)}; set init_qpos in the spec to choose the pose",
                AssemblerWarning,
                stacklevel=2,
            )
        return values

    @property
    def init_base_qpos(self) -> FloatArray | None:
        """The base joints' positions at each reset (``robosuite.init_base_qpos``), or None."""
        values = self._of_spec("init_base_qpos", lambda spec: spec.robosuite.init_base_qpos)
        return None if values is None else np.array(values, dtype=float)

    @property
    def init_torso_qpos(self) -> FloatArray | None:
        """The torso joints' positions at each reset (``robosuite.init_torso_qpos``), or None."""
        values = self._of_spec("init_torso_qpos", lambda spec: spec.robosuite.init_torso_qpos)
        return None if values is None else np.array(values, dtype=float)

    @property
    def base_xpos_offset(self) -> dict[str, Any]:
        """Per arena, robosuite's shapes: ``["table"]`` a function of the table length (positional),
        every other arena three numbers; arenas the spec leaves out get robosuite's defaults
        (:mod:`assembler.robosuite.placement`)."""
        if self._facts is not None:
            return in_robosuites_shape({arena: tuple(value) for arena, value in self._fact("arenas").items()})
        return offsets(self.spec)

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the robot's root to its top."""
        return np.array(self._of_spec("top_offset", lambda spec: spec.top_offset), dtype=float)

    @property
    def _horizontal_radius(self) -> float:
        return float(self._of_spec("horizontal_radius", lambda spec: spec.horizontal_radius))

    @property
    def gripper_mount_pos_offset(self) -> dict[str, Any]:
        """Empty: our assembly puts each gripper where the spec's ``gripper_mount`` says."""
        return {}

    @property
    def gripper_mount_quat_offset(self) -> dict[str, Any]:
        """Empty: our assembly puts each gripper where the spec's ``gripper_mount`` says."""
        return {}

    # ----- assembly, by the assembler -----------------------------------------------------

    def add_base(self, base: RobosuiteBase) -> None:
        """Stand our robot on the spec base of ``base``'s name; ``base`` keeps its name lists."""
        if self.base is not None:
            raise ValueError("Mount already added for this robot!")  # robosuite's words
        self._add(base, None)
        self.base = base
        self.cameras = self.get_element_names(self.worldbody, "camera")

    def add_gripper(self, gripper: RobosuiteGripper, arm_name: str | None = None) -> None:
        """Put our spec gripper of ``gripper``'s name on the arm whose end-effector body is ``arm_name``
        (every arm when None, as robosuite does)."""
        arms = self._arms_of(arm_name)
        if not arms:
            raise ValueError(f"{type(self).__name__} has no end-effector body named {arm_name}")
        for arm in arms:
            if self.eef_name[arm] in self.grippers:
                raise ValueError("Attempts to add multiple grippers to one body")  # robosuite's words
        self._add(gripper, arm_name)
        for arm in arms:
            self.grippers[self.eef_name[arm]] = gripper
        self.cameras = self.get_element_names(self.worldbody, "camera")

    def _arms_of(self, arm_name: str | None) -> list[str]:
        return [arm for arm in self.arms if arm_name is None or self.eef_name[arm] == arm_name]

    def _add(self, part: Any, arm_name: str | None) -> None:
        """Give our assembly ``part`` (a base, or a gripper for ``arm_name``'s arms): now when it is
        made, or when it is made later (robosuite's values answered by records); a part not of ours
        is looked up now, so that an error about it is raised here as before."""
        self._added.append((part, arm_name))
        if "_assembly" in self.__dict__:
            self._give(self.assembly, part, arm_name)
        elif inspect.getattr_static(type(part), "assembler_class", None) is None:
            self.assembly  # noqa: B018 (made now, given every part added so far, this one too)

    def _give(self, assembly: models.ManipulatorModel, part: Any, arm_name: str | None) -> None:
        if isinstance(part, RobosuiteBase):
            assembly.add_base(our_instance(REGISTRIES["base"], part))
            return
        for index, arm in enumerate(self._arms_of(arm_name)):
            ours = our_instance(REGISTRIES["gripper"], part, reuse=index == 0)  # one instance per hand
            assembly.add_gripper(ours, arm=arm)

    def _groups(self, kind: str) -> list[list[str]]:
        """robosuite's groups of ``kind`` (``joints`` or ``actuators``) in :data:`GROUPS` order: from
        the make record of the assembly as it stands, else from our assembly."""
        recorded = self._recorded()
        if recorded is None:
            return [list(getattr(self.assembly, f"{group}_{kind}")) for group in GROUPS]
        return [list(recorded[f"{group}_{kind}"]) for group in GROUPS]

    def update_joints(self) -> None:
        """robosuite's joint groups, from the spec's ``joint_groups`` (or robosuite's name rules)."""
        groups = self._groups("joints")
        self._arms_joints, self._base_joints, self._torso_joints = groups[:3]
        self._head_joints, self._legs_joints = groups[3:]

    def update_actuators(self) -> None:
        """robosuite's actuator groups: each actuator with the joint it drives."""
        groups = self._groups("actuators")
        self._arms_actuators, self._base_actuators, self._torso_actuators = groups[:3]
        self._head_actuators, self._legs_actuators = groups[3:]

    def set_mujoco_model(self, mujoco_model: Any = None) -> None:
        """Make our assembly the tree robosuite merges into the world, then compile it as robosuite does."""
        recorded = self._recorded()
        if recorded is not None and recorded["file"]:
            MujocoXML.__init__(self, recorded_assembly_file(recorded["file"], lambda: self.assembly, _world))
        else:
            MujocoXML.__init__(self, _world_file(self.assembly))
        self._point_elements_at_tree()
        self.cameras = self.get_element_names(self.worldbody, "camera")
        super().set_mujoco_model(mujoco_model)

    def _point_elements_at_tree(self) -> None:
        """robosuite's element lists (``_elements``) point into the tree it read first; point them at the
        same-named elements of the new one, so ``set_base_xpos``/``set_base_ori`` edit what is merged."""
        by_name = {(e.tag, e.get("name")): e for e in self.root.iter() if e.get("name")}
        for key, value in self._elements.items():
            if isinstance(value, list):
                self._elements[key] = [by_name.get((e.tag, e.get("name")), e) for e in value]
            else:
                self._elements[key] = by_name.get((value.tag, value.get("name")), value)


def _world(robot: models.RobotModel) -> mujoco.MjSpec:
    """The robot's assembly, checked for robosuite's world (:func:`.parts.world_checked`), built only
    when no file is kept for it."""
    from assembler.robosuite import parts

    return parts.world_checked(robot)


def _world_file(robot: models.RobotModel) -> str:
    """The file robosuite reads for ``robot`` with its base and grippers, the robot made now."""
    from assembler.robosuite import parts

    return parts.assembly_file(robot)


def our_instance(registry: Registry[P], given: Any, reuse: bool = True) -> P:
    """Our part for ``given`` (a robosuite gripper or base object): when it is one of
    ours, the very part whose model file robosuite read (its XML is read once; ``reuse``), else a new
    part made for robosuite of :func:`our_part`."""
    if reuse and inspect.getattr_static(type(given), "assembler_class", None) is not None:
        own = getattr(given, "part", None)
        if own is not None:
            return own  # type: ignore[no-any-return]
    from assembler.robosuite import parts  # robosuite gave a part that is not ours: ours is made now

    return parts.robosuite_part(our_part(registry, given), given.idn)


def our_part(registry: Registry[P], given: Any) -> type[P]:
    """Our spec class for ``given`` (a robosuite gripper or base object): its own when
    it is one of ours, else our spec of the same name, whose names must be robosuite's."""
    spec_class: type[P] | None = spec_class_of(type(given))
    if spec_class is None:
        name = type(given).__name__
        spec_class = registry.get(name)
        if spec_class is None:
            raise AssemblerError(
                f"robosuite's {registry.family} {name} has no spec: a spec robot is built from specs only; "
                f"write a {registry.family} spec named {name}, or pick one of {', '.join(sorted(registry))}"
            )
        check_same_names(given, spec_class)
    return spec_class


def robot_class(assembler_class: type[models.ManipulatorModel]) -> type[SpecRobot]:
    """The robosuite robot class of a spec robot (not yet in robosuite's registries)."""
    check_offsets(assembler_class)
    return robosuite_robot(assembler_class.spec.name, assembler_class.spec.arms, assembler_class)


def robosuite_robot(name: str, arms: Sequence[str], assembler_class: object) -> type[SpecRobot]:
    """The robosuite robot class ``name`` with ``arms``, whose ``assembler_class`` is the spec class
    or what stands for it until it is read (a registration record's
    :class:`~assembler.robosuite.registrations.SpecClassOf`)."""
    namespace: dict[str, Any] = {
        "assembler_class": assembler_class,
        "arms": list(arms),
        "__module__": __name__,
        "__doc__": f"{name} from its spec, for robosuite's environments.",
    }
    return QuietMeta(name, (SpecRobot,), namespace)


def check_offsets(assembler_class: type[models.ManipulatorModel]) -> None:
    """Raise the spec's error when robosuite cannot read one of its ``base_xpos_offset`` arenas."""
    spec = assembler_class.spec
    problems = []
    for arena in spec.base_xpos_offset:
        if arena != "table" and not _three_numbers(spec, arena):
            path = FieldPath(("base_xpos_offset", arena))
            message = (
                f"robosuite reads base_xpos_offset.{arena} as three numbers (only table's may use variables)"
            )
            problems.append(assembler_class.spec_problem(path, message))
    if problems:
        raise SpecError(problems)


def _three_numbers(spec: Any, arena: str) -> bool:
    """Whether the offset for ``arena`` needs no variable."""
    try:
        spec.resolve_base_xpos_offset(arena)
    except ExpressionError:
        return False
    return True
