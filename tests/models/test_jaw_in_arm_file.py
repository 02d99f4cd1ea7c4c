"""A jaw inside the arm's own file (SO-101, Fetch) declared as the robot's gripper: the robot spec
cuts it from the arm (remove_bodies), a gripper spec takes it from the same file (root_body), and
the assembly is the file as MuJoCo loads it, with the jaw's names under the gripper's prefix."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import MjcfError, SpecError

ARM_WITH_JAW = """\
<mujoco model="so101ish">
  <compiler angle="radian" autolimits="true"/>
  <asset><material name="jaw_mat" rgba="0.2 0.2 0.2 1"/></asset>
  <default>
    <default class="jaw"><joint damping="0.7"/></default>
  </default>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="cylinder" size="0.05 0.05" mass="2"/>
      <body name="link1" pos="0 0 0.1">
        <joint name="shoulder" axis="0 0 1" range="-2 2"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <body name="gripper_body" pos="0.3 0 0" euler="0 0.3 0">
          <geom name="fixed_jaw_col" type="box" size="0.02 0.01 0.04" mass="0.1" material="jaw_mat"/>
          <site name="grip_point" pos="0 0 0.05"/>
          <body name="moving_jaw" pos="0 0.02 0">
            <joint name="jaw" class="jaw" type="slide" axis="0 1 0" range="0 0.03"/>
            <geom name="moving_jaw_col" type="box" size="0.02 0.005 0.04" mass="0.05"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="act_shoulder" joint="shoulder" kp="200" ctrlrange="-2 2"/>
    <position name="act_jaw" joint="jaw" kp="50" ctrlrange="0 0.03"/>
  </actuator>
  <sensor>
    <jointpos name="jaw_pos" joint="jaw"/>
    <framepos name="grip_pos" objtype="site" objname="grip_point"/>
  </sensor>
</mujoco>
"""

ROBOT = """\
name: So101ish
mjcf: so101ish.xml
eef_bodies: {right: link1}
remove_bodies: [gripper_body]
default_grippers: {right: So101Jaw}
"""

JAW = """\
kind: gripper
name: So101Jaw
mjcf: so101ish.xml
root_body: gripper_body
eef_body: gripper_body
actions:
  dimensions: [{actuators: [act_jaw]}]
"""


@pytest.fixture
def folder(write: Callable[[str, str], Path]) -> Path:
    write("arm/so101ish.xml", ARM_WITH_JAW)
    write("arm/so101ish.yaml", ROBOT)
    return write("arm/so101_jaw.yaml", JAW).parent


def test_the_jaw_in_the_arms_file_is_the_robots_gripper(folder: Path) -> None:
    assembler.register_specs(folder)
    robot = assembler.assemble("So101ish")
    model = robot.get_model(cache=False)
    direct = mujoco.MjModel.from_xml_path(str(folder / "so101ish.xml"))

    assert robot.arm_joints["right"] == ["robot0_shoulder"]
    assert robot.grippers["right"].joints == ["gripper0_right_jaw"]
    assert [model.actuator(a).name for a in range(model.nu)] == [
        "robot0_act_shoulder",
        "gripper0_right_act_jaw",
    ]
    assert (model.nbody, model.njnt, model.nsensor, model.nu) == (
        direct.nbody,
        direct.njnt,
        direct.nsensor,
        direct.nu,
    )
    jaw_material = model.geom("gripper0_right_fixed_jaw_col").matid[0]
    assert model.mat(jaw_material).name == "gripper0_right_jaw_mat"  # the arm keeps its copy, unused
    np.testing.assert_allclose(model.mat_rgba[jaw_material], direct.mat_rgba[0])
    assert model.joint("gripper0_right_jaw").damping[0] == pytest.approx(0.7)  # the jaw's default class
    ours, theirs = mujoco.MjData(model), mujoco.MjData(direct)
    mujoco.mj_kinematics(model, ours)
    mujoco.mj_kinematics(direct, theirs)
    for name in ("gripper_body", "moving_jaw"):
        np.testing.assert_allclose(
            ours.body(f"gripper0_right_{name}").xpos, theirs.body(name).xpos, atol=1e-9
        )
        np.testing.assert_allclose(
            ours.body(f"gripper0_right_{name}").xquat, theirs.body(name).xquat, atol=1e-9
        )


def test_a_root_body_the_file_lacks_is_named_at_the_gripper_spec(folder: Path) -> None:
    (folder / "so101_jaw.yaml").write_text(JAW.replace("root_body: gripper_body", "root_body: gripper"))
    (cls,) = assembler.register_specs(folder / "so101_jaw.yaml")
    with pytest.raises(
        MjcfError, match=r"so101_jaw.yaml:4:12: root_body: .*so101ish.xml: no body named 'gripper'"
    ):
        cls(idn=0).check()


def test_a_removed_body_the_file_lacks_is_a_spec_problem(folder: Path) -> None:
    (folder / "so101ish.yaml").write_text(ROBOT.replace("[gripper_body]", "[grip]"))
    assembler.register_specs(folder)
    with pytest.raises(
        SpecError, match=r"so101ish.yaml:4:17: remove_bodies\[0\]: no body named 'grip' in the MJCF"
    ):
        assembler.create_robot("So101ish").check()
