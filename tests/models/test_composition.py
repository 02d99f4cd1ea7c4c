"""Bases and grippers: each merging strategy on tiny inline MJCF, the keyframe, groups and errors."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import AssemblerError, RegistryError, SpecError


def _tree(model: mujoco.MjModel) -> dict[str, str]:
    """body -> parent body."""
    return {model.body(i).name: model.body(model.body(i).parentid[0]).name for i in range(1, model.nbody)}


def _forward(model: mujoco.MjModel) -> mujoco.MjData:
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    return data


def test_mount_is_merged_into_the_robot_root_at_the_offset(parts: Path) -> None:
    robot = assembler.create_robot("TwoLink", idn=0)
    robot.add_base(assembler.create_base("TestMount", idn=0))
    model = robot.get_model()
    assert _tree(model)["fixed_mount0_base"] == "robot0_base"
    # robosuite's offset: the robot root's own position (0, 0, 0.1) minus the mount's top offset
    np.testing.assert_allclose(model.body("fixed_mount0_base").pos, [0, 0, 0.11])
    # bottom offset: mount root pos (-0.5) - top offset (-0.01) + robot root pos (0.1)
    np.testing.assert_allclose(robot.bottom_offset, [0, 0, -0.39])
    assert robot.horizontal_radius == 0.5  # max(robot 0.5, mount 0.3)
    assert model.geom("fixed_mount0_post_col").rgba.tolist() == [0.5, 0.5, 0.5, 1.0]  # the file's


def test_mobile_base_goes_between_the_root_and_the_arm(parts: Path) -> None:
    robot = assembler.assemble("TwoLink", idn=1, base="TestMobile", grippers={})
    model = robot.get_model()
    tree = _tree(model)
    assert tree["mobilebase1_base"] == "robot1_base"
    assert tree["robot1_manipulator_mount"] == "mobilebase1_support"  # prefixed, unlike robosuite
    assert tree["robot1_link1"] == "robot1_manipulator_mount"
    assert model.camera("robot1_robotview").bodyid[0] == model.body("robot1_manipulator_mount").id
    assert robot.base_joints == ["mobilebase1_joint_mobile_forward", "mobilebase1_joint_mobile_yaw"]
    assert robot.torso_joints == ["mobilebase1_joint_torso_height"]
    assert robot.torso_actuators == ["mobilebase1_actuator_torso"]
    assert robot.arm_joints == ["robot1_shoulder", "robot1_elbow"]
    assert robot.all_joints == robot.joints + robot.base.joints  # type: ignore[union-attr]
    # the base's actuators and sensors came along
    assert (
        model.actuator("mobilebase1_actuator_mobile_forward").trnid[0]
        == model.joint("mobilebase1_joint_mobile_forward").id
    )
    assert model.sensor("mobilebase1_torso_pos").objid[0] == model.joint("mobilebase1_joint_torso_height").id


def test_two_mobile_robots_share_a_scene_without_name_collisions(parts: Path, write) -> None:  # type: ignore[no-untyped-def]
    scene_file = write(
        "scenes/two.yaml",
        "kind: scene\nname: pair\nrobots:\n"
        "  - {robot: TwoLink, base: TestMobile, pos: [0, 0.6, 0]}\n"
        "  - {robot: TwoLink, base: TestMobile, pos: [0, -0.6, 0], ori: [0, 0, 3.14159]}\n",
    )
    scene = assembler.load_scene(scene_file)
    model = scene.get_model()
    assert {"robot0_manipulator_mount", "robot1_manipulator_mount"} <= set(_tree(model))
    data = _forward(model)
    assert data.body("robot1_base").xpos[1] == pytest.approx(-0.6)
    np.testing.assert_allclose(data.qpos[model.joint("mobilebase1_joint_torso_height").qposadr[0]], 0.2)
    # Each robot's controls stay together: its arm, then its base (robosuite's order), robot by robot.
    prefixes = [model.actuator(i).name.split("_")[0] for i in range(model.nu)]
    assert prefixes == sorted(prefixes, key=lambda p: p[-1]) and prefixes.index(
        "mobilebase0"
    ) < prefixes.index("robot1")
    assert prefixes.index("robot0") < prefixes.index("mobilebase0")


def test_legged_base_moves_its_free_joint_to_the_robot_root(parts: Path) -> None:
    robot = assembler.assemble("TwoLink", base="TestLegs")
    model = robot.get_model()
    root = model.body("robot0_base")
    free = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    assert [model.jnt_bodyid[j] for j in free] == [root.id]
    assert _tree(model)["robot0_manipulator_mount"] == "leg0_support"
    assert robot.legs_joints == ["leg0_fr_hip_leg", "leg0_fl_hip_leg"]
    assert robot.legs_actuators == ["leg0_fr_act", "leg0_fl_act"]  # every actuator type
    data = _forward(model)
    legs = [model.joint(j).qposadr[0] for j in robot.legs_joints]
    np.testing.assert_allclose(data.qpos[legs], [0.3, -0.3])  # the base's init_qpos in the keyframe


def test_null_base_adds_only_its_sites(parts: Path) -> None:
    robot = assembler.assemble("TwoLink", base="TestNull")
    model = robot.get_model()
    assert model.site("nullbase0_center").bodyid[0] == 0
    assert "nullbase0_support" not in _tree(model)


def test_a_second_base_is_an_error(parts: Path) -> None:
    robot = assembler.assemble("TwoLink", base="TestMount")
    with pytest.raises(
        AssemblerError, match=r"TwoLink0 already has the base TestMount0; a robot stands on one base"
    ):
        robot.add_base(assembler.create_base("TestNull"))


def test_missing_support_body_is_named(parts: Path, write, monkeypatch: pytest.MonkeyPatch) -> None:  # type: ignore[no-untyped-def]
    monkeypatch.setenv("ASSEMBLER_ALLOW_PATHS", str(parts.parent))  # the MJCF sits in a sibling folder
    assembler.register_specs(
        write(
            "parts2/nosupport.yaml", "kind: base\nname: NoSupport\ntype: mobile\nmjcf: ../parts/mount.xml\n"
        )
    )
    robot = assembler.assemble("TwoLink", base="NoSupport")
    with pytest.raises(
        SpecError,
        match=r"nosupport.yaml:1:1: support_body: no body named 'support' in the MJCF. Bodies: base$",
    ):
        robot.get_model()


def test_gripper_attaches_at_the_hand_with_the_mount_override(parts: Path, two_link: Path) -> None:
    two_link.write_text(
        "name: TwoLink\nmjcf: twolink.xml\ninit_qpos: [0.5, -0.5]\ndefault_grippers: {right: TestPinch}\n"
        "gripper_mount:\n  right: {pos: [0, 0, 0.02], quat: [1, 0, 0, 0]}\n"
    )
    assembler.register_specs(two_link)
    robot = assembler.assemble("TwoLink", idn=0)
    model = robot.get_model()
    assert _tree(model)["gripper0_right_pinch_root"] == "robot0_right_hand"
    np.testing.assert_allclose(model.body("gripper0_right_pinch_root").pos, [0, 0, 0.02])
    np.testing.assert_allclose(model.body("gripper0_right_pinch_root").quat, [1, 0, 0, 0])
    gripper = robot.grippers["right"]
    assert gripper.important_geoms == {"right_fingerpad": ["gripper0_right_finger_pad_col"]}
    assert gripper.important_sites["grip_site"] == "gripper0_right_grip_site"
    assert gripper.dof == 1 and gripper.joints == ["gripper0_right_finger_joint"]
    assert model.opt.timestep == 0.002  # the robot's options win over the gripper's
    data = _forward(model)
    assert data.qpos[model.joint("gripper0_right_finger_joint").qposadr[0]] == pytest.approx(0.02)
    # the rotation offset comes from real poses after the override: hand parent -> grip frame
    hand_quat = model.body("robot0_right_hand").quat
    expected = np.zeros(4)
    mujoco.mju_mulQuat(expected, hand_quat, np.array([0.0, 1.0, 0.0, 0.0]))  # eef quat in the gripper
    np.testing.assert_allclose(robot.eef_rot_offset["right"], expected[[1, 2, 3, 0]], atol=1e-12)


def test_one_gripper_per_arm_and_never_shared(parts: Path) -> None:
    robot = assembler.create_robot("TwoLink", idn=0)
    gripper = assembler.create_gripper("TestPinch", idn="0_right")
    robot.add_gripper(gripper, arm="right")
    with pytest.raises(AssemblerError, match=r"TwoLink0's right arm already has TestPinch0_right"):
        robot.add_gripper(assembler.create_gripper("TestPinch", idn="0_right"), arm="right")
    with pytest.raises(AssemblerError, match=r"has no left arm; its arms: right"):
        robot.add_gripper(gripper, arm="left")


def test_missing_end_effector_body_is_named(parts: Path, write) -> None:  # type: ignore[no-untyped-def]
    (cls,) = assembler.register_specs(
        write("robots/handless.yaml", "name: Handless\nmjcf: twolink.xml\neef_bodies: {right: tool0}\n")
    )
    robot = cls(idn=0)
    robot.add_gripper(assembler.create_gripper("TestPinch", idn="0_right"), arm="right")
    with pytest.raises(
        SpecError,
        match=r"handless.yaml:3:21: eef_bodies.right: no body named 'tool0' in the MJCF. "
        r"Bodies: base, link1, link2, right_hand$",
    ):
        robot.get_model()


def test_dangling_important_names_are_refused(parts: Path, write) -> None:  # type: ignore[no-untyped-def]
    (cls,) = assembler.register_specs(
        write(
            "parts/bad_pinch.yaml",
            "kind: gripper\nname: BadPinch\nmjcf: pinch.xml\nimportant_geoms: {left_fingerpad: [finger1_pad]}\n",
        )
    )
    with pytest.raises(
        SpecError,
        match=r"bad_pinch.yaml:4:36: important_geoms.left_fingerpad\[0\]: no geom named 'finger1_pad' in the "
        r"MJCF. Did you mean 'finger_pad_col'\? Geoms: finger_pad_col, palm_col$",
    ):
        cls(idn="0_right").check()


def test_unknown_base_and_gripper_names_suggest(parts: Path) -> None:
    with pytest.raises(RegistryError, match=r"unknown base 'TestMobil'. Did you mean 'TestMobile'\?"):
        assembler.assemble("TwoLink", base="TestMobil")
    with pytest.raises(RegistryError, match=r"unknown gripper 'TestPintch'. Did you mean 'TestPinch'\?"):
        assembler.assemble("TwoLink", grippers={"right": "TestPintch"})


def test_set_joint_attribute_still_works_after_a_mobile_base(parts: Path) -> None:
    # robosuite's add_mobile_base deep-copies the arm and set_joint_attribute silently does nothing
    robot = assembler.assemble("TwoLink", base="TestMobile")
    robot.set_joint_attribute("damping", np.array([0.7, 0.8]))
    model = robot.get_model()
    assert model.joint("robot0_elbow").damping[0] == pytest.approx(0.8)


def test_legged_robot_removes_actuation_and_lists_stay_consistent(parts: Path, write) -> None:  # type: ignore[no-untyped-def]
    write("robots/legged_arm.xml", LEGGED_ARM)
    (cls,) = assembler.register_specs(
        write(
            "robots/legged_arm.yaml",
            "name: LeggedArm\nmjcf: legged_arm.xml\nmorphology: legged_manipulator\n"
            "remove_actuation: ['*_leg']\nremove_free_joint: true\n",
        )
    )
    robot = cls(idn=0)
    assert robot.joints == ["robot0_arm_joint"]
    assert robot.dof == 1 and robot.actuators == ["robot0_arm_act"]
    robot.set_joint_attribute("damping", np.ones(robot.dof))
    model = robot.get_model()
    assert model.njnt == 1 and model.nu == 1 and model.ntendon == 0 and model.neq == 0
    assert [model.sensor(i).name for i in range(model.nsensor)] == ["robot0_arm_pos"]
    # the rules indexed every joint before the removal (robosuite's order)
    assert model.joint("robot0_arm_joint").armature == pytest.approx(5.0 / 3)


LEGGED_ARM = """\
<mujoco>
  <worldbody>
    <body name="pelvis" pos="0 0 1">
      <freejoint/>
      <geom name="pelvis_col" type="sphere" size="0.1" mass="5"/>
      <body name="thigh"><joint name="left_leg" axis="0 1 0" range="-1 1"/><geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.04" mass="2"/></body>
      <body name="thigh2"><joint name="right_leg" axis="0 1 0" range="-1 1"/><geom type="capsule" fromto="0 0 0 0 0 -0.4" size="0.04" mass="2"/></body>
      <body name="arm" pos="0 0 0.3"><joint name="arm_joint" axis="0 1 0" range="-2 2"/><geom type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <body name="right_hand" pos="0.3 0 0"/></body>
    </body>
  </worldbody>
  <tendon><fixed name="legs"><joint joint="left_leg" coef="1"/><joint joint="right_leg" coef="1"/></fixed></tendon>
  <equality><joint joint1="left_leg" joint2="right_leg"/><joint joint1="right_leg"/></equality>
  <actuator>
    <velocity name="left_act" joint="left_leg" kv="1"/>
    <general name="right_act" joint="right_leg"/>
    <general name="legs_act" tendon="legs"/>
    <position name="arm_act" joint="arm_joint" kp="50"/>
  </actuator>
  <sensor>
    <jointpos name="left_pos" joint="left_leg"/>
    <actuatorfrc name="right_frc" actuator="right_act"/>
    <tendonpos name="legs_pos" tendon="legs"/>
    <jointpos name="arm_pos" joint="arm_joint"/>
  </sensor>
</mujoco>
"""


def test_a_part_with_its_own_options_leaves_no_log_file(parts: Path, tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    # the gripper's <option timestep="0.001"> differs from the robot's: MuJoCo would warn and write
    # MUJOCO_LOG.TXT into the working directory if the assembler let the conflict reach it
    monkeypatch.chdir(tmp_path)
    robot = assembler.assemble("TwoLink", grippers={"right": "TestPinch"})
    assert robot.get_model().opt.timestep == 0.002
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()


EMPTY_SUPPORT_MJCF = """\
<mujoco model="empty_support">
  <worldbody>
    <body name="support">
      <joint name="joint_mobile_forward" type="slide" axis="1 0 0"/>
      <site name="center" size="0.01"/>
    </body>
  </worldbody>
</mujoco>
"""
"""robosuite's NullMobileBase in miniature: a moving support body with no mass of its own."""


def test_a_massless_mobile_base_compiles_alone_with_a_stand_in_load(
    write,
) -> None:
    write("empty_support.xml", EMPTY_SUPPORT_MJCF)
    (cls,) = assembler.register_specs(
        write("empty_support.yaml", "kind: base\nname: EmptySupport\ntype: mobile\nmjcf: empty_support.xml\n")
    )
    model = cls(idn=0).compile_alone()
    assert model.body("mobilebase0_support_stand_in_load").mass[0] == 1.0


def test_world_level_elements_of_a_robot_stay_in_the_world_on_a_mobile_base(
    parts: Path, two_link: Path
) -> None:
    text = two_link.with_suffix(".xml").read_text()
    text = text.replace(
        "<worldbody>",
        """<asset>
    <mesh name="marker" vertex="0 0 0  0.1 0 0  0 0.1 0  0 0 0.1"/>
    <material name="paint" rgba="1 0 0 1"/>
  </asset>
  <worldbody>
    <geom name="floor_marker" type="mesh" mesh="marker" material="paint" group="1" contype="0" conaffinity="0"/>
    <camera name="overview" pos="2 0 1" xyaxes="0 1 0 -0.5 0 1"/>""",
        1,
    )
    two_link.with_suffix(".xml").write_text(text)
    model = assembler.assemble("TwoLink", base="TestMobile").get_model()
    geom, camera = model.geom("robot0_floor_marker"), model.camera("robot0_overview")
    assert geom.bodyid[0] == 0 and camera.bodyid[0] == 0  # the world, not the moving base
    assert model.mesh(int(geom.dataid[0])).name == "robot0_marker"
    assert model.material(int(geom.matid[0])).name == "robot0_paint"
