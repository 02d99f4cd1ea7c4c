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

import warnings
from collections.abc import Sequence
from typing import Any, ClassVar, TypeVar

import numpy as np
from robosuite.models.base import MujocoXML
from robosuite.models.bases import RobotBaseModel as RobosuiteBase
from robosuite.models.grippers import GripperModel as RobosuiteGripper
from robosuite.models.robots.manipulators.manipulator_model import ManipulatorModel as RobosuiteManipulator
from robosuite.models.robots.robot_model import RobotModelMeta

from assembler.errors import AssemblerError, AssemblerWarning, SpecError
from assembler.models import REGISTERED_BASES, REGISTERED_GRIPPERS, ManipulatorModel, PartModel
from assembler.models.part import FloatArray
from assembler.models.registering import Registry
from assembler.robosuite.conventions import base_in_robosuite
from assembler.robosuite.parts import assembly_file, part_file, robosuite_part
from assembler.robosuite.placement import offsets
from assembler.robosuite.same_names import check_same_names
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema.expressions import ExpressionError

P = TypeVar("P", bound=PartModel)

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

    assembler_class: ClassVar[type[ManipulatorModel] | None] = None
    """The assembler's class for the spec."""

    arms: ClassVar[list[str]] = []
    """The arms, right first (robosuite reads them from the class)."""

    base: Any
    """robosuite's base object the robot stands on (None until ``add_base``)."""

    def __init__(self, idn: int | str = 0) -> None:
        if self.assembler_class is None:
            raise AssemblerError("SpecRobot is made per spec: use assembler.robosuite.robot_class(name)")
        self.assembly: ManipulatorModel = robosuite_part(self.assembler_class, idn)
        """Our robot, base and grippers, built the assembler's way."""
        super().__init__(part_file(self.assembly), idn=idn)

    # ----- what robosuite reads from the spec ---------------------------------------------

    @property
    def spec(self) -> Any:
        """The robot's validated spec."""
        return self.assembly.spec

    @property
    def arm_type(self) -> str:
        """single or bimanual."""
        return str(self.spec.arm_type)

    @property
    def _eef_name(self) -> dict[str, str]:
        return {arm: self.spec.eef_body(arm) for arm in self.arms}

    @property
    def default_base(self) -> str:
        """The spec's base, or its ``robosuite.stand_in_base`` (robosuite cannot build a robot without)."""
        return str(base_in_robosuite(self.spec))

    @property
    def default_gripper(self) -> dict[str, str | None]:
        """Per arm, the spec's gripper (None: robosuite's null gripper)."""
        return {arm: self.spec.default_grippers.get(arm) for arm in self.arms}

    @property
    def default_controller_config(self) -> dict[str, str]:
        """Controller config name per body part (robosuite's fallback for parts its config lacks)."""
        return dict(self.spec.default_controller_config)

    @property
    def init_qpos(self) -> FloatArray:
        """The spec's initial joint positions; without them, the model file's ``qpos0`` (each joint's
        ``ref``, zero unless the file says otherwise), said once per robot: robosuite resets to it."""
        if self.spec.init_qpos is None and self.spec.name not in _WITHOUT_INIT_QPOS:
            _WITHOUT_INIT_QPOS.add(self.spec.name)
            warnings.warn(
                f"{self.assembly.describe()} has no init_qpos: robosuite resets its joints to the model "
                f"file's qpos0 {list(self.assembly.init_qpos)}; set init_qpos in the spec to choose the pose",
                AssemblerWarning,
                stacklevel=2,
            )
        return self.assembly.init_qpos

    @property
    def init_base_qpos(self) -> FloatArray | None:
        """The base joints' positions at each reset (``robosuite.init_base_qpos``), or None."""
        values = self.spec.robosuite.init_base_qpos
        return None if values is None else np.array(values, dtype=float)

    @property
    def init_torso_qpos(self) -> FloatArray | None:
        """The torso joints' positions at each reset (``robosuite.init_torso_qpos``), or None."""
        values = self.spec.robosuite.init_torso_qpos
        return None if values is None else np.array(values, dtype=float)

    @property
    def base_xpos_offset(self) -> dict[str, Any]:
        """Per arena, robosuite's shapes: ``["table"]`` a function of the table length (positional),
        every other arena three numbers; arenas the spec leaves out get robosuite's defaults
        (:mod:`assembler.robosuite.placement`)."""
        return offsets(self.spec)

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the robot's root to its top."""
        return np.array(self.spec.top_offset, dtype=float)

    @property
    def _horizontal_radius(self) -> float:
        return float(self.spec.horizontal_radius)

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
        self.assembly.add_base(our_instance(REGISTERED_BASES, base))
        self.base = base
        self.cameras = self.get_element_names(self.worldbody, "camera")

    def add_gripper(self, gripper: RobosuiteGripper, arm_name: str | None = None) -> None:
        """Put our spec gripper of ``gripper``'s name on the arm whose end-effector body is ``arm_name``
        (every arm when None, as robosuite does)."""
        arms = [arm for arm in self.arms if arm_name is None or self.eef_name[arm] == arm_name]
        if not arms:
            raise ValueError(f"{type(self).__name__} has no end-effector body named {arm_name}")
        for index, arm in enumerate(arms):
            if self.eef_name[arm] in self.grippers:
                raise ValueError("Attempts to add multiple grippers to one body")  # robosuite's words
            part = our_instance(REGISTERED_GRIPPERS, gripper, reuse=index == 0)  # one instance per hand
            self.assembly.add_gripper(part, arm=arm)
            self.grippers[self.eef_name[arm]] = gripper
        self.cameras = self.get_element_names(self.worldbody, "camera")

    def update_joints(self) -> None:
        """robosuite's joint groups, from the spec's ``joint_groups`` (or robosuite's name rules)."""
        self._arms_joints = list(self.assembly.arm_joints)
        self._base_joints = self.assembly.base_joints
        self._torso_joints = self.assembly.torso_joints
        self._head_joints = self.assembly.head_joints
        self._legs_joints = self.assembly.legs_joints

    def update_actuators(self) -> None:
        """robosuite's actuator groups: each actuator with the joint it drives."""
        self._arms_actuators = list(self.assembly.arm_actuators)
        self._base_actuators = self.assembly.base_actuators
        self._torso_actuators = self.assembly.torso_actuators
        self._head_actuators = self.assembly.head_actuators
        self._legs_actuators = self.assembly.legs_actuators

    def set_mujoco_model(self, mujoco_model: Any = None) -> None:
        """Make our assembly the tree robosuite merges into the world, then compile it as robosuite does."""
        MujocoXML.__init__(self, assembly_file(self.assembly))
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


def our_instance(registry: Registry[P], given: Any, reuse: bool = True) -> P:
    """Our part for ``given`` (a robosuite gripper or base object): when it is one of
    ours, the very part whose model file robosuite read (its XML is read once; ``reuse``), else a new
    part made for robosuite of :func:`our_part`."""
    own = getattr(given, "part", None)
    if reuse and getattr(type(given), "assembler_class", None) is not None and own is not None:
        return own  # type: ignore[no-any-return]
    return robosuite_part(our_part(registry, given), given.idn)


def our_part(registry: Registry[P], given: Any) -> type[P]:
    """Our spec class for ``given`` (a robosuite gripper or base object): its own when
    it is one of ours, else our spec of the same name, whose names must be robosuite's."""
    spec_class = getattr(type(given), "assembler_class", None)
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


def robot_class(assembler_class: type[ManipulatorModel]) -> type[SpecRobot]:
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


def check_offsets(assembler_class: type[ManipulatorModel]) -> None:
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
