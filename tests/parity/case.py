"""One parity case: a robot with a base, grippers, an idn and what a user does to it afterwards
(placement, joint attributes), and our side of it, built the way a user would build it."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import mujoco
import numpy as np

import assembler

DEFAULT = "default"


@dataclass(frozen=True)
class Case:
    """What both sides assemble. ``gripper`` goes on every arm (None: each arm's default gripper)."""

    robot: str
    base: str = DEFAULT
    gripper: str | None = None
    idn: int | str = 0
    xpos: tuple[float, float, float] | None = None
    ori: tuple[float, float, float] | None = None
    joint_attribute: tuple[str, bool] | None = None
    """(attribute, force): ``set_joint_attribute`` with :func:`joint_attribute_values`."""

    @property
    def id(self) -> str:
        """A short readable name, e.g. ``Panda/base=Spot`` or ``Baxter/gripper=NullGripper``."""
        parts = [self.robot]
        if self.base != DEFAULT:
            parts.append(f"base={self.base}")
        if self.gripper is not None:
            parts.append(f"gripper={self.gripper}")
        if self.idn != 0:
            parts.append(f"idn={self.idn}")
        if self.xpos is not None or self.ori is not None:
            parts.append("placed")
        if self.joint_attribute is not None:
            parts.append(f"{self.joint_attribute[0]}(force={self.joint_attribute[1]})")
        return "/".join(parts)

    @property
    def base_name(self) -> str | None:
        """The base actually used (the robot's default base resolved)."""
        robot = assembler.REGISTERED_ROBOTS[self.robot]
        return robot.spec.default_base if self.base == DEFAULT else self.base

    @property
    def base_type(self) -> str | None:
        """mount, mobile, legged or null; None without a base."""
        name = self.base_name
        return assembler.REGISTERED_BASES[name].spec.type if name is not None else None

    @property
    def arms(self) -> tuple[str, ...]:
        return tuple(assembler.REGISTERED_ROBOTS[self.robot].spec.arms)


def joint_attribute_values(dof: int) -> np.ndarray:
    """A different value per joint, so a value landing on the wrong joint shows."""
    return np.linspace(0.2, 0.8, dof)


def build_ours(case: Case, edit: Callable[[mujoco.MjSpec], object] | None = None) -> mujoco.MjModel:
    """Our compiled model: ``assemble``, then placement and joint attributes as a user calls them;
    ``edit`` changes the assembled spec before it is compiled (the oracle's own tests)."""
    grippers = dict.fromkeys(case.arms, case.gripper) if case.gripper is not None else None
    robot = assembler.assemble(case.robot, idn=case.idn, base=case.base, grippers=grippers)
    if case.xpos is not None:
        robot.set_base_xpos(np.array(case.xpos))
    if case.ori is not None:
        robot.set_base_ori(np.array(case.ori))
    if case.joint_attribute is not None:
        attribute, force = case.joint_attribute
        robot.set_joint_attribute(attribute, joint_attribute_values(robot.dof), force=force)
    if edit is not None:
        edit(robot.mjspec)
    return robot.get_model()
