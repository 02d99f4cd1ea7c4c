"""``assembler new`` on a fixed-base robot with two arms under one torso: written ``arm_type: bimanual``
with each arm's joints, end effector and hand its own (never one hand spanning both arms), and one
arm with a side word in its names stays one arm. Real files and real compiles."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.registry.catalog import register_specs

LINK = '<inertial pos="0 0 0" mass="0.5" diaginertia="0.001 0.001 0.001"/>'


def _arm(prefix: str, y: float) -> str:
    """Three hinges reaching forward from the torso at ``y``, then a hand with two sliding fingers."""
    capsule = '<geom type="capsule" size="0.03" fromto="0 0 0 0.2 0 0"/>'
    finger = (
        '<body name="{p}finger_{n}" pos="0.05 {y} 0">{link}<joint name="{p}finger_{n}_joint" type="slide" '
        'axis="0 1 0" range="-0.02 0.02"/><geom type="box" size="0.02 0.005 0.01" contype="0" '
        'conaffinity="0"/></body>'
    )
    fingers = "".join(finger.format(p=prefix, n=n, y=s * 0.02, link=LINK) for n, s in (("a", 1), ("b", -1)))
    return f"""
        <body name="{prefix}upper" pos="0 {y} 0.2">{LINK}{capsule}
          <joint name="{prefix}shoulder" axis="0 0 1" range="-2 2"/>
          <body name="{prefix}lower" pos="0.2 0 0">{LINK}{capsule}
            <joint name="{prefix}elbow" axis="0 1 0" range="-2 2"/>
            <body name="{prefix}wrist" pos="0.2 0 0">{LINK}
              <joint name="{prefix}wrist_pitch" axis="0 1 0" range="-2 2"/>
              <geom type="sphere" size="0.03"/>
              <body name="{prefix}palm" pos="0.05 0 0">{LINK}
                <geom type="box" size="0.02 0.04 0.02" contype="0" conaffinity="0"/>{fingers}
              </body>
            </body>
          </body>
        </body>"""


def _robot(arms: str) -> str:
    """A column, a torso turning on a waist at its top, a head, and ``arms`` on the torso; no actuators."""
    return f"""<mujoco model="twin">
  <worldbody>
    <body name="column" pos="0 0 0">{LINK}
      <geom type="cylinder" size="0.1 0.4" pos="0 0 0.4"/>
      <body name="chest" pos="0 0 0.8">{LINK}
        <joint name="waist" axis="0 0 1" range="-1 1"/>
        <geom type="box" size="0.1 0.15 0.15" pos="0 0 0.15" contype="0" conaffinity="0"/>
        <body name="head" pos="0 0 0.35">{LINK}
          <joint name="head_pan" axis="0 0 1" range="-1 1"/>
          <geom type="sphere" size="0.08" contype="0" conaffinity="0"/>
        </body>{arms}
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def _written(write: Callable[[str, str], Path], text: str) -> tuple[dict[str, object], Path]:
    model = write("robots/twin.xml", text)
    spec = model.with_name("twin.yaml")
    assert main(["new", str(model), "-o", str(spec)]) == 0
    return yaml.safe_load(spec.read_text()), spec


@pytest.mark.parametrize(
    ("right", "left"),
    [("right_", "left_"), ("p_", "q_")],
    ids=["sides by name", "sides by where the arms lie"],
)
def test_two_arms_on_one_torso_are_written_bimanual_each_with_its_own_hand(
    write: Callable[[str, str], Path], right: str, left: str
) -> None:
    fields, spec = _written(write, _robot(_arm(right, -0.2) + _arm(left, 0.2)))
    assert fields["morphology"] == "manipulator" and fields["arm_type"] == "bimanual"
    arm = ["shoulder", "elbow", "wrist_pitch"]
    assert fields["joint_groups"] == {
        "right": [right + joint for joint in arm],
        "left": [left + joint for joint in arm],
        "torso": ["waist"],  # on the midline, moving both arms
        "head": ["head_pan"],
    }
    assert fields["eef_bodies"] == {
        "right": f"{right}palm",
        "left": f"{left}palm",
    }  # where each hand's fingers branch
    # Each hand stays in its own arm: no gripper cut from a body holding both hands (the torso).
    assert fields["default_grippers"] == {"right": None, "left": None}
    assert "remove_bodies" not in fields and [p.name for p in spec.parent.iterdir()] == [
        "twin.xml",
        "twin.yaml",
    ]
    comments = " ".join(line.strip("# ") for line in spec.read_text().splitlines() if line.startswith("#"))
    assert (
        f"each hand is the file's own (right: {right}finger_a_joint, {right}finger_b_joint; left:" in comments
    )
    (cls,) = register_specs(spec)
    robot = assembler.create_robot(cls.__name__, idn=0)
    assert robot.arms == ("right", "left")
    assert robot.arm_joints["left"] == [f"robot0_{left}{joint}" for joint in arm]
    fingers = {j for j in robot.joints if "finger" in j}
    assert len(fingers) == 4 and not fingers & set(robot.arm_joints)
    model = robot.get_model()
    assert model.nu == 12  # a servo on every joint: 6 arm joints, waist, head, 4 fingers


@pytest.mark.parametrize("prefix", ["right_", "left_"])
def test_one_arm_named_by_its_side_stays_one_arm(write: Callable[[str, str], Path], prefix: str) -> None:
    fields, _ = _written(write, _robot(_arm(prefix, -0.2)))
    assert "arm_type" not in fields  # single, robosuite's Sawyer's right_j0 ... names
    joint_groups = fields["joint_groups"]
    assert isinstance(joint_groups, dict)
    assert joint_groups["right"] == ["waist", *(prefix + j for j in ("shoulder", "elbow", "wrist_pitch"))]
