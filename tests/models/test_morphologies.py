"""Bimanual and humanoid bodies from YAML; MJCF default classes that robosuite cannot parse."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import SpecError

TORSO_MJCF = """\
<mujoco>
  <default>
    <default class="body">
      <joint damping="2"/>
      <default class="arm">
        <joint armature="0.3" range="-2 2"/>
        <geom type="capsule" size="0.03" mass="1"/>
      </default>
    </default>
  </default>
  <worldbody>
    <body name="pelvis" pos="0 0 1" childclass="body">
      <freejoint/>
      <geom name="pelvis_col" type="sphere" size="0.1" mass="5"/>
      <body name="torso" pos="0 0 0.2">
        <joint name="torso_yaw" axis="0 0 1" range="-1 1"/>
        <geom name="torso_col" type="box" size="0.1 0.15 0.1" mass="5"/>
        <body name="head" pos="0 0 0.2"><joint name="head_pan" axis="0 0 1" range="-1 1"/><geom type="sphere" size="0.08" mass="1"/></body>
        <body name="r_upper" pos="0 -0.25 0.1" childclass="arm">
          <joint name="r_shoulder" axis="0 1 0"/><geom fromto="0 0 0 0 0 -0.25"/>
          <body name="right_eef" pos="0 0 -0.3"/>
        </body>
        <body name="l_upper" pos="0 0.25 0.1" childclass="arm">
          <joint name="l_shoulder" axis="0 1 0"/><geom fromto="0 0 0 0 0 -0.25"/>
          <body name="left_eef" pos="0 0 -0.3"/>
        </body>
      </body>
      <body name="l_thigh" pos="0 0.1 -0.1"><joint name="l_leg_hip" axis="0 1 0" range="-1 1"/><geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05" mass="3"/></body>
      <body name="r_thigh" pos="0 -0.1 -0.1"><joint name="r_leg_hip" axis="0 1 0" range="-1 1"/><geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.05" mass="3"/></body>
    </body>
  </worldbody>
  <actuator>
    <motor name="torso_yaw" joint="torso_yaw"/><motor name="head_pan" joint="head_pan"/>
    <motor name="r_shoulder" joint="r_shoulder"/><motor name="l_shoulder" joint="l_shoulder"/>
    <motor name="l_leg_hip" joint="l_leg_hip"/><motor name="r_leg_hip" joint="r_leg_hip"/>
  </actuator>
</mujoco>
"""


@pytest.fixture
def humanoid(write) -> Path:  # type: ignore[no-untyped-def]
    write("h/torso.xml", TORSO_MJCF)
    return write(
        "h/humanoid.yaml",
        "name: Mini\nmjcf: torso.xml\nmorphology: humanoid\narm_type: bimanual\n"
        "eef_bodies: {right: right_eef, left: left_eef}\nremove_free_joint: true\n",
    )


def test_humanoid_groups_follow_robosuite_rules_without_prefixes(humanoid: Path) -> None:
    (cls,) = assembler.register_specs(humanoid)
    robot = cls(idn=0)
    assert isinstance(robot, assembler.HumanoidModel)
    assert robot.arms == ("right", "left")
    assert robot.torso_joints == ["robot0_torso_yaw"]
    assert robot.head_joints == ["robot0_head_pan"]
    assert robot.legs_joints == ["robot0_l_leg_hip", "robot0_r_leg_hip"]
    assert robot.arm_joints == ["robot0_r_shoulder", "robot0_l_shoulder"]
    assert robot.arm_joints["left"] == ["robot0_l_shoulder"]
    assert robot.arm_actuators["right"] == ["robot0_r_shoulder"]
    assert robot.eef_name == {"right": "robot0_right_eef", "left": "robot0_left_eef"}


def test_nested_classes_and_childclass_resolve_as_mujoco_does(humanoid: Path) -> None:
    (cls,) = assembler.register_specs(humanoid)
    robot = cls(idn=0)
    model = robot.get_model()
    # r_shoulder: childclass 'arm' nested in 'body' -> damping 2, armature 0.3, range -2..2 degrees
    # (the file keeps MuJoCo's default angle unit, degrees, and the assembly honours it)
    shoulder = model.joint("robot0_r_shoulder")
    assert shoulder.damping[0] == 2.0 and shoulder.armature[0] == pytest.approx(0.3)
    np.testing.assert_allclose(shoulder.range, np.deg2rad([-2, 2]))
    reloaded = mujoco.MjModel.from_xml_string(robot.get_xml())
    np.testing.assert_allclose(reloaded.joint("robot0_r_shoulder").range, np.deg2rad([-2, 2]))
    assert str(robot.joint_values["r_shoulder"]["armature"].source) == "mjcf (class 'arm')"
    # torso_yaw: childclass 'body' only -> damping 2, armature from the rule (index 0)
    assert model.joint("robot0_torso_yaw").armature[0] == 5.0
    assert model.body("robot0_torso").mass[0] == pytest.approx(5.0)


def test_declared_groups_win_over_name_rules(humanoid: Path) -> None:
    humanoid.write_text(
        humanoid.read_text()
        + "joint_groups:\n  torso: [torso_yaw, head_pan]\n  right: [r_*]\n  left: [l_shoulder]\n  legs: [l_leg_hip]\n"
    )
    (cls,) = assembler.register_specs(humanoid)
    robot = cls(idn=0)
    assert robot.torso_joints == ["robot0_torso_yaw", "robot0_head_pan"]
    assert robot.head_joints == []
    assert robot.arm_joints["right"] == ["robot0_r_shoulder", "robot0_r_leg_hip"]


def test_upper_body_humanoid_without_legs(humanoid: Path) -> None:
    humanoid.write_text(
        humanoid.read_text().replace("morphology: humanoid", "morphology: humanoid_upper_body")
        + "remove_actuation: ['*_leg_*']\n"
    )
    (cls,) = assembler.register_specs(humanoid)
    robot = cls(idn=0)
    assert isinstance(robot, assembler.HumanoidUpperBodyModel)
    assert robot.legs_joints == [] and robot.dof == 4
    assert mujoco.MjModel.from_xml_string(robot.get_xml()).nu == 4


def test_humanoid_must_be_bimanual(write) -> None:  # type: ignore[no-untyped-def]
    spec = write("h/bad.yaml", "name: Bad\nmjcf: torso.xml\nmorphology: humanoid\n")
    with pytest.raises(
        SpecError, match=r"bad.yaml:1:1: Value error, a humanoid has two arms: set arm_type: bimanual"
    ):
        assembler.register_specs(spec)


def test_bimanual_robot_takes_a_gripper_per_arm(humanoid: Path, parts: Path) -> None:
    (cls,) = assembler.register_specs(humanoid)
    robot = cls(idn=0)
    robot.add_gripper(assembler.create_gripper("TestPinch", idn="0_right"), arm="right")
    robot.add_gripper(assembler.create_gripper("TestPinch", idn="0_left"), arm="left")
    with pytest.raises(assembler.AssemblerError, match="say which one the gripper goes on"):
        robot.add_gripper(assembler.create_gripper("TestPinch", idn="0_x"))
    model = robot.get_model()
    assert model.body("gripper0_left_pinch_root").parentid[0] == model.body("robot0_left_eef").id
    assert model.body("gripper0_right_pinch_root").parentid[0] == model.body("robot0_right_eef").id
