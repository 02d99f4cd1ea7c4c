"""Declared joint groups do what docs/spec.md says: arm lists, when given, are the whole arms."""

from __future__ import annotations

from pathlib import Path

import assembler


def _robot(two_link: Path, groups: str) -> assembler.ManipulatorModel:
    two_link.write_text(two_link.read_text() + f"joint_groups: {groups}\n")
    (cls,) = assembler.register_specs(two_link)
    robot = cls(idn=0)
    assert isinstance(robot, assembler.ManipulatorModel)
    return robot


def test_an_arm_list_leaves_unlisted_joints_out_of_every_arm(two_link: Path) -> None:
    robot = _robot(two_link, "{right: [shoulder]}")
    assert robot.arm_joints["right"] == ["robot0_shoulder"]
    assert robot.arm_actuators["right"] == ["robot0_act_shoulder"]
    assert robot.group_of("elbow") == "unassigned"
    assert (robot.torso_joints, robot.head_joints, robot.base_joints) == ([], [], [])


def test_without_arm_lists_every_joint_no_group_claims_is_an_arm_joint(two_link: Path) -> None:
    robot = _robot(two_link, "{torso: [shoulder]}")
    assert robot.torso_joints == ["robot0_shoulder"]
    assert robot.arm_joints["right"] == ["robot0_elbow"]
