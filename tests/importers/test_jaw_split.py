"""``assembler new`` on an arm whose file holds its own jaw (pybullet's Panda, Fetch): the hand is cut
from the arm and written as a gripper spec beside the arm's, so the jaw gets an action in robosuite
and +1 closes it, as robosuite's grippers close. Real URDF files, real compiles, robosuite stepping."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import numpy as np
import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.registry.catalog import register_specs

INERTIA = '<inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/>'


def _link(name: str, mass: float, box: str, z: float = 0.0) -> str:
    return f"""
  <link name="{name}">
    <inertial><mass value="{mass}"/>{INERTIA}</inertial>
    <collision><origin xyz="0 0 {z}"/><geometry><box size="{box}"/></geometry></collision>
  </link>"""


def _joint(name: str, kind: str, parent: str, child: str, xyz: str, axis: str, limit: str) -> str:
    return f"""
  <joint name="{name}" type="{kind}">
    <parent link="{parent}"/><child link="{child}"/><origin xyz="{xyz}"/><axis xyz="{axis}"/>{limit}
  </joint>"""


ARM = f"""<?xml version="1.0"?>
<robot name="pincher">
  {_link("base", 2.0, "0.1 0.1 0.1")}
  {_link("upper", 1.0, "0.04 0.04 0.3", 0.15)}
  {_link("fore", 0.5, "0.04 0.04 0.3", 0.15)}
  {_link("hand", 0.3, "0.04 0.1 0.03")}
  {_link("left_finger", 0.05, "0.01 0.01 0.05", 0.025)}
  {_link("right_finger", 0.05, "0.01 0.01 0.05", 0.025)}
  {_joint("shoulder", "revolute", "base", "upper", "0 0 0.05", "0 1 0", '<limit lower="-2" upper="2" effort="30" velocity="2"/>')}
  {_joint("elbow", "revolute", "upper", "fore", "0 0 0.3", "0 1 0", '<limit lower="-2" upper="2" effort="20" velocity="2"/>')}
  {_joint("wrist_fixed", "fixed", "fore", "hand", "0 0 0.3", "0 0 1", "")}
  {_joint("finger_joint1", "prismatic", "hand", "left_finger", "0 0.02 0.015", "0 1 0", '<limit lower="0" upper="0.03" effort="20" velocity="0.2"/>')}
  {_joint("finger_joint2", "prismatic", "hand", "right_finger", "0 -0.02 0.015", "0 -1 0", '<limit lower="0" upper="0.03" effort="20" velocity="0.2"/>')}
</robot>
"""
"""A two-joint arm whose hand, welded to the forearm, carries two sliding fingers (0: closed)."""


@pytest.fixture
def written(write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]) -> tuple[Path, Path]:
    model = write("pincher/pincher.urdf", ARM)
    spec = model.with_suffix(".yaml")
    assert main(["new", str(model), "-o", str(spec)]) == 0
    out = capsys.readouterr().out
    jaw = spec.with_name("pincher_jaw.yaml")
    assert out.startswith(
        f"wrote {spec} and {jaw}: robot Pincher with its jaw PincherJaw (validated and compiled)"
    )
    return spec, jaw


def test_the_hand_is_cut_from_the_arm_and_written_as_the_robots_gripper(written: tuple[Path, Path]) -> None:
    spec, jaw = written
    arm, hand = yaml.safe_load(spec.read_text()), yaml.safe_load(jaw.read_text())
    assert (arm["eef_bodies"], arm["remove_bodies"], arm["default_grippers"]) == (
        {"right": "fore"},
        ["hand"],
        {"right": "PincherJaw"},
    )
    assert arm["joint_groups"] == {"right": ["shoulder", "elbow"]} and len(arm["init_qpos"]) == 2
    assert (hand["kind"], hand["root_body"], hand["urdf"]) == ("gripper", "hand", arm["urdf"])
    register_specs(jaw)
    (robot,) = register_specs(spec)
    model = assembler.assemble(robot.__name__, base=None).get_model()
    names = {model.joint(j).name for j in range(model.njnt)}
    assert names == {
        "robot0_shoulder",
        "robot0_elbow",
        "gripper0_right_finger_joint1",
        "gripper0_right_finger_joint2",
    }


@pytest.mark.filterwarnings("ignore::assembler.errors.AssemblerWarning")  # the bridge's added frames
def test_in_robosuite_the_jaw_has_an_action_and_plus_one_closes_it(written: tuple[Path, Path]) -> None:
    robosuite = pytest.importorskip("robosuite", reason="robosuite is not installed (the robosuite extra)")
    bridge = pytest.importorskip("assembler.robosuite")
    spec, jaw = written
    bridge.register(str(jaw), str(spec))
    env = robosuite.make(
        "Lift", robots="Pincher", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False
    )
    env.reset()
    assert env.robots[0].gripper["right"].dof == 1
    finger = env.sim.model.joint_name2id("gripper0_right_finger_joint1")
    address = env.sim.model.jnt_qposadr[finger]
    arm_still = np.zeros(env.action_dim - 1)
    for _ in range(30):
        env.step(np.r_[arm_still, -1.0])  # open
    opened = float(env.sim.data.qpos[address])
    for _ in range(30):
        env.step(np.r_[arm_still, 1.0])  # close
    closed = float(env.sim.data.qpos[address])
    env.close()
    assert opened > 0.025 and closed < 0.005  # open near 0.03, closed near 0 (the range's low end)
