"""``assembler new`` on a fixed-base robot with two arms under one torso: written ``arm_type: bimanual``
with each arm's joints, end effector and hand its own (never one hand spanning both arms), each hand
welded to its arm cut into a gripper spec of its own so that robosuite gives it an action, and one
arm with a side word in its names stays one arm. Real files, real compiles, robosuite stepping."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.importers import snake_case
from assembler.registry.catalog import register_specs

LINK = '<inertial pos="0 0 0" mass="0.5" diaginertia="0.001 0.001 0.001"/>'

FINGER_GEOM = 'size="0.02 0.005 0.01" contype="0" conaffinity="0"'
"""A finger's box, colliding with nothing."""


def _arm(prefix: str, y: float, palm_joint: str = "", finger_geom: str = FINGER_GEOM) -> str:
    """Three hinges reaching forward from the torso at ``y``, then a hand (welded to the wrist, unless
    ``palm_joint`` is a joint of its own) with two fingers sliding towards each other as they close
    (0.02 apart at the low end of their range, 0.06 at the high end), each a box of ``finger_geom``."""
    capsule = '<geom type="capsule" size="0.03" fromto="0 0 0 0.2 0 0"/>'
    finger = (
        '<body name="{p}finger_{n}" pos="0.05 {y} 0">{link}<joint name="{p}finger_{n}_joint" type="slide" '
        'axis="0 {s} 0" range="-0.01 0.01"/><geom type="box" ' + finger_geom + "/></body>"
    )
    fingers = "".join(
        finger.format(p=prefix, n=n, y=s * 0.02, s=s, link=LINK) for n, s in (("a", 1), ("b", -1))
    )
    return f"""
        <body name="{prefix}upper" pos="0 {y} 0.2">{LINK}{capsule}
          <joint name="{prefix}shoulder" axis="0 0 1" range="-2 2"/>
          <body name="{prefix}lower" pos="0.2 0 0">{LINK}{capsule}
            <joint name="{prefix}elbow" axis="0 1 0" range="-2 2"/>
            <body name="{prefix}wrist" pos="0.2 0 0">{LINK}
              <joint name="{prefix}wrist_pitch" axis="0 1 0" range="-2 2"/>
              <geom type="sphere" size="0.03"/>
              <body name="{prefix}palm" pos="0.05 0 0">{LINK}{palm_joint}
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
def test_two_arms_on_one_torso_are_written_bimanual_each_hand_cut_into_its_own_gripper(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str], right: str, left: str
) -> None:
    fields, spec = _written(write, _robot(_arm(right, -0.2) + _arm(left, 0.2)))
    said = capsys.readouterr().out
    assert fields["morphology"] == "manipulator" and fields["arm_type"] == "bimanual"
    arm = ["shoulder", "elbow", "wrist_pitch"]
    assert fields["joint_groups"] == {
        "right": [right + joint for joint in arm],
        "left": [left + joint for joint in arm],
        "torso": ["waist"],  # on the midline, moving both arms
        "head": ["head_pan"],
    }
    # Each hand (where its fingers branch) is cut from its own arm, never one body holding both hands
    # (the torso), and mounted back on the body it hung from as that arm's gripper.
    assert fields["eef_bodies"] == {"right": f"{right}wrist", "left": f"{left}wrist"}
    assert fields["remove_bodies"] == [f"{right}palm", f"{left}palm"]
    name = fields["name"]  # Twin, or TwinArm once robosuite holds a Twin (registered by a test before)
    assert fields["default_grippers"] == {"right": f"{name}RightJaw", "left": f"{name}LeftJaw"}
    jaw_files = [spec.with_name(f"{snake_case(name)}_{side}_jaw.yaml") for side in ("right", "left")]
    assert sorted(spec.parent.iterdir()) == sorted([spec, spec.with_suffix(".xml"), *jaw_files])
    # the line new ends with names every file it wrote and both jaws
    assert f"{jaw_files[0].name} and " in said and f"{jaw_files[1].name}: robot {name} with its jaws " in said
    assert f"with its jaws {name}RightJaw and {name}LeftJaw (validated and compiled)" in said
    for side, prefix, jaw_file in (("right", right, jaw_files[0]), ("left", left, jaw_files[1])):
        jaw = yaml.safe_load(jaw_file.read_text())
        assert (jaw["kind"], jaw["name"], jaw["root_body"], jaw["mjcf"]) == (
            "gripper",
            f"{name}{side.title()}Jaw",
            f"{prefix}palm",
            fields["mjcf"],
        )
        assert [servo["match"] for servo in jaw["actuators"]] == [
            f"{prefix}finger_a_joint",
            f"{prefix}finger_b_joint",
        ]
    robot = assembler.assemble(_registered(spec), base=None)
    assert robot.arms == ("right", "left")
    assert robot.arm_joints["left"] == [f"robot0_{left}{joint}" for joint in arm]
    model = robot.get_model()
    joints = {model.joint(j).name for j in range(model.njnt)}
    for side, prefix in (("right", right), ("left", left)):  # each hand on its own arm, with its names
        assert {
            f"gripper0_{side}_{prefix}finger_a_joint",
            f"gripper0_{side}_{prefix}finger_b_joint",
        } <= joints
        assert robot.grippers[side].dof == 1
    assert model.nu == 12  # a servo on every joint: 6 arm joints, waist, head, 4 fingers


def _registered(spec: Path) -> str:
    """The robot of ``spec`` registered with the jaw specs beside it, by name."""
    jaws = sorted(spec.parent.glob("*_jaw.yaml"))
    if jaws:
        register_specs(*jaws)
    (cls,) = register_specs(spec)
    return cls.__name__


@pytest.mark.filterwarnings("ignore::assembler.errors.AssemblerWarning")  # the bridge's added frames
def test_in_robosuites_two_arm_lift_each_hand_has_an_action_and_plus_one_closes_it(
    write: Callable[[str, str], Path],
) -> None:
    robosuite = pytest.importorskip("robosuite", reason="robosuite is not installed (the robosuite extra)")
    bridge = pytest.importorskip("assembler.robosuite")
    fields, spec = _written(write, _robot(_arm("right_", -0.2) + _arm("left_", 0.2)))
    bridge.register(*sorted(map(str, spec.parent.glob("*_jaw.yaml"))), str(spec))
    env = robosuite.make(
        "TwoArmLift",
        robots=fields["name"],
        env_configuration="single-robot",
        has_renderer=False,
        has_offscreen_renderer=False,
        use_camera_obs=False,
    )
    env.reset()
    robot = env.robots[0]
    assert {arm: robot.gripper[arm].dof for arm in robot.arms} == {"right": 1, "left": 1}
    model = env.sim.model
    fingers = {
        side: [
            model.jnt_qposadr[model.joint_name2id(f"gripper0_{side}_{side}_finger_{n}_joint")] for n in "ab"
        ]
        for side in robot.arms
    }
    arms = sum(robot.part_controllers[arm].control_dim for arm in robot.arms)
    assert env.action_dim == arms + 2  # one dimension per hand
    reached = {}
    for value in (-1.0, 1.0):  # open, then close, both hands at once
        action = robot.create_action_vector({robot.get_gripper_name(arm): [value] for arm in robot.arms})
        for _ in range(30):
            env.step(action)
        reached[value] = {side: env.sim.data.qpos[addresses].copy() for side, addresses in fingers.items()}
    env.close()
    for side in robot.arms:  # open near the range's high end (0.01), closed near its low end (-0.01)
        assert np.all(reached[-1.0][side] > 0.008) and np.all(reached[1.0][side] < -0.008), side


def test_fingers_overlapping_at_home_are_kept_from_colliding_so_that_the_jaw_closes(
    write: Callable[[str, str], Path],
) -> None:
    """Fingers whose collision boxes overlap (a box 0.1 wide in y, each 0.02 off the hand's middle)
    would be pushed apart by MuJoCo from the first step, and the jaw would not close."""
    wide = 'size="0.02 0.05 0.01"'  # colliding, as geoms do by default
    arms = _arm("right_", -0.2, finger_geom=wide) + _arm("left_", 0.2, finger_geom=wide)
    fields, spec = _written(write, _robot(arms))
    name = str(fields["name"])
    for side in ("right", "left"):
        jaw = yaml.safe_load(spec.with_name(f"{snake_case(name)}_{side}_jaw.yaml").read_text())
        assert jaw["contact_excludes"] == [[f"{side}_finger_a", f"{side}_finger_b"]]
    model = assembler.assemble(_registered(spec), base=None).get_model()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    home = data.qpos.copy()
    data.ctrl[:] = home[model.jnt_qposadr[model.actuator_trnid[:, 0]]]
    fingers = [a for a in range(model.nu) if "finger" in model.actuator(a).name]
    data.ctrl[fingers] = -0.01  # closed: the low end of their range
    for _ in range(round(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
    joints = model.actuator_trnid[fingers, 0]
    np.testing.assert_allclose(data.qpos[model.jnt_qposadr[joints]], -0.01, atol=1e-3)


def test_a_hand_turning_on_a_joint_of_its_own_stays_in_its_arm_while_the_other_is_cut(
    write: Callable[[str, str], Path],
) -> None:
    roll = '<joint name="left_palm_roll" axis="1 0 0" range="-2 2"/>'
    fields, spec = _written(write, _robot(_arm("right_", -0.2) + _arm("left_", 0.2, roll)))
    assert fields["remove_bodies"] == ["right_palm"]  # cutting left_palm would cut left_palm_roll
    assert fields["default_grippers"] == {"right": f"{fields['name']}RightJaw", "left": None}
    assert fields["eef_bodies"] == {"right": "right_wrist", "left": "left_palm"}
    joint_groups = fields["joint_groups"]
    assert isinstance(joint_groups, dict) and joint_groups["left"][-1] == "left_palm_roll"
    comments = " ".join(line.strip("# ") for line in spec.read_text().splitlines() if line.startswith("#"))
    assert "the hand is the file's own (left: left_finger_a_joint, left_finger_b_joint)" in comments
    assert [p.name for p in spec.parent.glob("*_jaw.yaml")] == [
        f"{snake_case(str(fields['name']))}_right_jaw.yaml"
    ]
    model = assembler.assemble(_registered(spec), base=None).get_model()
    joints = {model.joint(j).name for j in range(model.njnt)}
    assert {"gripper0_right_right_finger_a_joint", "robot0_left_finger_a_joint"} <= joints


@pytest.mark.parametrize("prefix", ["right_", "left_"])
def test_one_arm_named_by_its_side_stays_one_arm(write: Callable[[str, str], Path], prefix: str) -> None:
    fields, _ = _written(write, _robot(_arm(prefix, -0.2)))
    assert "arm_type" not in fields  # single, robosuite's Sawyer's right_j0 ... names
    joint_groups = fields["joint_groups"]
    assert isinstance(joint_groups, dict)
    assert joint_groups["right"] == ["waist", *(prefix + j for j in ("shoulder", "elbow", "wrist_pitch"))]
