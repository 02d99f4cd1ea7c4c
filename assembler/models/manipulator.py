"""ManipulatorModel: a robot with one (right) or two (right, left) arms, grippers on their hands.

Also the joint and actuator groups (arm, torso, head, legs, base): declared in the spec or by
robosuite's name rules on unprefixed names, with per-arm lists robosuite lacks.
"""

from __future__ import annotations

import mujoco
import numpy as np

from assembler.errors import AssemblerError, Problem
from assembler.mjcf import compose
from assembler.models.gripper_model import GripperModel
from assembler.models.groups import PerArm, arm_side, robosuite_group
from assembler.models.joint_rules import matching_joints
from assembler.models.part import FloatArray, PartModel
from assembler.models.preparation import PreparedPart
from assembler.models.robot_model import RobotModel
from assembler.spec.fieldpath import FieldPath

UNASSIGNED = "unassigned"
"""The group of a joint that the spec's arm lists leave out and no other group claims."""


class ManipulatorModel(RobotModel):
    """A robot arm or arms; grippers attach at the end-effector bodies."""

    in_registry = False

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self.grippers: dict[str, GripperModel] = {}

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        check = self.name_check(prepared)
        # The end-effector bodies the spec names, and the default ones where a gripper goes by default.
        with_gripper = {arm for arm, gripper in self.spec.default_grippers.items() if gripper}
        for arm in self.arms:
            if arm in self.spec.eef_bodies or arm in with_gripper:
                check.body(FieldPath(("eef_bodies", arm)), self.spec.eef_body(arm))
        return [*super()._name_problems(prepared), *check.problems]

    # ----- arms and grippers --------------------------------------------------------------

    @property
    def arm_type(self) -> str:
        """single or bimanual."""
        return self.spec.arm_type

    @property
    def arms(self) -> tuple[str, ...]:
        """The arms, right first."""
        return self.spec.arms

    @property
    def eef_name(self) -> dict[str, str]:
        """End-effector body per arm (prefixed)."""
        return {arm: self.naming_prefix + self.spec.eef_body(arm) for arm in self.arms}

    @property
    def models(self) -> list[PartModel]:
        """Sub-models attached to this robot: its base, then its grippers (right first)."""
        return [*super().models, *self.grippers.values()]

    def add_gripper(self, gripper: GripperModel, arm: str | None = None) -> None:
        """Attach ``gripper`` at ``arm``'s end-effector body (default: the robot's only arm)."""
        if arm is None:
            if len(self.arms) != 1:
                raise AssemblerError(
                    f"{self.name} has arms {', '.join(self.arms)}: say which one the gripper goes on "
                    "(one gripper instance cannot sit on two hands)"
                )
            arm = self.arms[0]
        if arm not in self.arms:
            raise AssemblerError(f"{self.name} has no {arm} arm; its arms: {', '.join(self.arms)}")
        if arm in self.grippers:
            raise AssemblerError(f"{self.name}'s {arm} arm already has {self.grippers[arm].name}")
        if any(existing is gripper for existing in self.grippers.values()):
            raise AssemblerError(f"{gripper.name} is already on another arm; create one gripper per arm")
        if not isinstance(gripper, GripperModel):
            raise AssemblerError(
                f"add_gripper expects a gripper (create_gripper(...)), got {type(gripper).__name__}"
            )
        self.grippers[arm] = gripper
        self._changed()

    def _attach_grippers(self, assembly: mujoco.MjSpec) -> None:
        for arm, gripper in self.grippers.items():
            mount = self.spec.gripper_mount.get(arm)  # type: ignore[call-overload]
            compose.attach_gripper(
                assembly,
                self.eef_name[arm],
                gripper.part_mjspec(),
                gripper.naming_prefix,
                mount.pos if mount else None,
                mount.quat if mount else None,
            )

    @property
    def eef_rot_offset(self) -> dict[str, FloatArray]:
        """Per arm, the rotation (x, y, z, w) from the hand's parent link to the grip frame.

        Computed from the compiled assembly's poses, after the gripper mount override, unlike
        robosuite (which multiplies XML quaternions before its own override). Without a gripper
        the grip frame is the hand body itself.
        """
        model = self.get_model()
        data = mujoco.MjData(model)
        mujoco.mj_kinematics(model, data)
        offsets = {}
        for arm in self.arms:
            hand = model.body(self.eef_name[arm])
            frame = self.grippers[arm].eef_body if arm in self.grippers else self.eef_name[arm]
            parent = data.xquat[hand.parentid[0]]
            relative = np.zeros(4)
            conjugate = np.zeros(4)
            mujoco.mju_negQuat(conjugate, parent)
            mujoco.mju_mulQuat(relative, conjugate, data.body(frame).xquat)
            offsets[arm] = relative[[1, 2, 3, 0]]
        return offsets

    # ----- groups -------------------------------------------------------------------------

    def group_of(self, joint: str) -> str:
        """torso, head, legs, base, right or left for one of the robot's own joints; ``unassigned``
        for a joint that declared arm lists leave out (no arm, no controller)."""
        declared = self.spec.joint_groups
        if declared is not None:
            for group in ("torso", "head", "legs", "base", "right", "left"):
                if any(matching_joints(p, [joint]) for p in getattr(declared, group)):
                    return group
            if declared.right or declared.left:  # the arms are listed: what they leave out is no arm's
                return UNASSIGNED
        else:
            by_name = robosuite_group(joint)
            if by_name is not None:
                return by_name
        return arm_side(joint, self.arms)

    def _joint_groups(self) -> dict[str, list[str]]:
        groups: dict[str, list[str]] = {g: [] for g in ("torso", "head", "legs", "base", "right", "left")}
        for joint in self.joint_names:
            groups.setdefault(self.group_of(joint), []).append(self.naming_prefix + joint)
        base = self.base
        if base is not None:
            for joint, prefixed in zip(base.joint_names, base.joints, strict=True):
                groups.setdefault(base.group_of(joint), []).append(prefixed)
        return groups

    def actuator_groups(self) -> dict[str, list[str]]:
        """Group (torso, head, legs, base, right, left) -> the actuators (prefixed) driving its joints."""
        by_joint = {joint: group for group, joints in self._joint_groups().items() for joint in joints}
        groups: dict[str, list[str]] = {g: [] for g in ("torso", "head", "legs", "base", "right", "left")}
        parts: list[PartModel] = [self] + ([self.base] if self.base is not None else [])
        for part in parts:
            for actuator in part.prepared_mjspec.actuators:
                if not actuator.name:
                    continue
                target = part.naming_prefix + actuator.target
                name = part.naming_prefix + actuator.name
                group = (
                    by_joint.get(target)
                    or robosuite_group(actuator.name)
                    or arm_side(actuator.name, self.arms)
                )
                groups.setdefault(group, []).append(name)
        return groups

    @property
    def arm_joints(self) -> PerArm:
        """Arm joints in order; ``arm_joints["right"]`` / ``["left"]`` for one arm."""
        groups = self._joint_groups()
        return PerArm({arm: groups[arm] for arm in self.arms})

    @property
    def arm_actuators(self) -> PerArm:
        """Arm actuators in order; ``arm_actuators["right"]`` for one arm."""
        groups = self.actuator_groups()
        return PerArm({arm: groups[arm] for arm in self.arms})

    @property
    def torso_joints(self) -> list[str]:
        """Torso joints (the robot's and its base's)."""
        return self._joint_groups()["torso"]

    @property
    def head_joints(self) -> list[str]:
        """Head joints."""
        return self._joint_groups()["head"]

    @property
    def legs_joints(self) -> list[str]:
        """Leg joints (the robot's and a legged base's)."""
        return self._joint_groups()["legs"]

    @property
    def base_joints(self) -> list[str]:
        """Joints that move the whole robot (a mobile base's)."""
        return self._joint_groups()["base"]

    @property
    def torso_actuators(self) -> list[str]:
        """Actuators driving torso joints."""
        return self.actuator_groups()["torso"]

    @property
    def head_actuators(self) -> list[str]:
        """Actuators driving head joints."""
        return self.actuator_groups()["head"]

    @property
    def legs_actuators(self) -> list[str]:
        """Actuators driving leg joints."""
        return self.actuator_groups()["legs"]

    @property
    def base_actuators(self) -> list[str]:
        """Actuators moving the whole robot."""
        return self.actuator_groups()["base"]


class LeggedManipulatorModel(ManipulatorModel):
    """A manipulator with legs; the spec may remove the legs' actuation and the free joint."""

    in_registry = False


class HumanoidModel(ManipulatorModel):
    """A full-body humanoid: two arms with end-effectors, torso, head and legs."""

    in_registry = False


class HumanoidUpperBodyModel(ManipulatorModel):
    """An upper-body humanoid: two arms with end-effectors, torso and head, no legs."""

    in_registry = False


class LeggedModel(ManipulatorModel):
    """A legged robot without arms (a quadruped, a biped): it stands on its ``feet``, has no end effector
    and takes no gripper."""

    in_registry = False

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        check = self.name_check(prepared)
        for index, foot in enumerate(self.spec.feet):
            check.body(FieldPath(("feet", index)), foot)
        return [*super()._name_problems(prepared), *check.problems]

    @property
    def feet(self) -> list[str]:
        """The bodies the robot stands on (prefixed)."""
        return [self.naming_prefix + foot for foot in self.spec.feet]


MORPHOLOGY_CLASSES: dict[str, type[RobotModel]] = {
    "manipulator": ManipulatorModel,
    "legged_manipulator": LeggedManipulatorModel,
    "humanoid": HumanoidModel,
    "humanoid_upper_body": HumanoidUpperBodyModel,
    "legged": LeggedModel,
}
"""The model class each robot spec's ``morphology`` becomes a subclass of."""
