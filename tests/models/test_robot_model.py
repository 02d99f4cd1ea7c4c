"""RobotModel: prefixing, names, joint attributes, placement and the home keyframe."""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import JointAttributeError, MjcfError, SpecError
from assembler.models.provenance import Provenance


@pytest.fixture
def robot(two_link: Path) -> assembler.RobotModel:
    assembler.register_specs(two_link)
    return assembler.create_robot("TwoLink", idn=3)


def test_every_name_and_reference_carries_the_prefix(robot: assembler.RobotModel) -> None:
    model = robot.get_model()
    names = [model.joint(i).name for i in range(model.njnt)]
    names += [model.body(i).name for i in range(1, model.nbody)]
    names += [model.actuator(i).name for i in range(model.nu)]
    assert all(name.startswith("robot3_") for name in names)
    # the actuators still drive the right joints after renaming
    assert model.joint(model.actuator("robot3_act_elbow").trnid[0]).name == "robot3_elbow"


def test_names_dof_and_lists(robot: assembler.RobotModel) -> None:
    assert robot.naming_prefix == "robot3_"
    assert robot.name == "TwoLink3"
    assert robot.dof == 2
    assert robot.joints == ["robot3_shoulder", "robot3_elbow"]
    assert robot.actuators == ["robot3_act_shoulder", "robot3_act_elbow"]
    assert robot.cameras == ["robot3_robotview"]
    assert robot.root_body == "robot3_base"
    assert robot.bodies == ["robot3_base", "robot3_link1", "robot3_link2", "robot3_right_hand"]
    assert robot.contact_geoms == ["robot3_base_col", "robot3_link1_col", "robot3_link2_col"]
    assert robot.visual_geoms == ["robot3_link1_vis"]
    assert robot.all_joints == robot.joints and robot.models == []


def test_collision_geoms_keep_the_files_colour_unless_the_spec_asks_for_robosuites(
    robot: assembler.RobotModel, two_link: Path
) -> None:
    model = robot.get_model()
    assert model.geom("robot3_link1_col").rgba.tolist() == [0.5, 0.5, 0.5, 1.0]  # MuJoCo's default grey
    two_link.write_text(two_link.read_text() + "collision_colour: robosuite\n")
    (cls,) = assembler.register_specs(two_link)
    model = cls(idn=3).get_model()
    assert model.geom("robot3_link1_col").rgba.tolist() == [0.0, 0.5, 0.0, 1.0]
    assert model.geom("robot3_link1_vis").rgba.tolist() == [1.0, 1.0, 1.0, 1.0]


def test_two_instances_are_independent_and_can_share_a_model(two_link: Path) -> None:
    assembler.register_specs(two_link)
    first = assembler.create_robot("TwoLink", idn=0)
    second = assembler.create_robot("TwoLink", idn=1)
    first.set_joint_attribute("damping", np.full(2, 0.9))
    assert second.get_model().joint("robot1_elbow").damping[0] == 3.0
    scene = mujoco.MjSpec()
    scene.attach(first.mjspec, frame=scene.worldbody.add_frame(pos=[0, 1, 0]))
    scene.attach(second.mjspec, frame=scene.worldbody.add_frame(pos=[0, -1, 0]))
    assert scene.compile().njnt == 4


def test_set_joint_attribute_force_and_unset_semantics(robot: assembler.RobotModel) -> None:
    robot.set_joint_attribute("damping", np.full(robot.dof, 0.5), force=True)
    model = robot.get_model()
    assert [model.joint(j).damping[0] for j in robot.joints] == [0.5, 0.5]
    assert robot.joint_values["elbow"]["damping"].source == Provenance("api")
    robot.set_joint_attribute("stiffness", np.array([1.0, 2.0]), force=False)  # unset: applied
    robot.set_joint_attribute("armature", np.array([9.0, 9.0]), force=False)  # all set: no-op
    model = robot.get_model()
    assert model.joint("robot3_elbow").stiffness[0] == 2.0
    assert model.joint("robot3_elbow").armature == pytest.approx(2.5)  # the rule's, kept


def test_set_joint_attribute_size_mismatch_is_a_clear_error(robot: assembler.RobotModel) -> None:
    with pytest.raises(
        JointAttributeError,
        match=r"^set_joint_attribute\('damping'\): expected 2 values \(one per joint: robot3_shoulder, robot3_elbow\), got 3$",
    ):
        robot.set_joint_attribute("damping", np.ones(3))
    with pytest.raises(
        JointAttributeError,
        match="unsupported attribute 'dampng'; supported: frictionloss, damping",
    ):
        robot.set_joint_attribute("dampng", np.ones(2))


def test_set_base_xpos_accounts_for_the_bottom_offset(robot: assembler.RobotModel) -> None:
    # the root body sits at z=0.1 in the file: its bottom offset
    np.testing.assert_allclose(robot.bottom_offset, [0, 0, 0.1])
    robot.set_base_xpos(np.array([0.5, 0.0, 0.0]))
    model = robot.get_model()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    np.testing.assert_allclose(data.body("robot3_base").xpos, [0.5, 0.0, -0.1])


def test_set_base_ori_rotates_by_roll_then_pitch_then_yaw_about_the_moving_axes_as_robosuite(
    robot: assembler.RobotModel,
) -> None:
    # robosuite's euler2mat gives Rx(roll) Ry(pitch) Rz(yaw); Rz Ry Rx would send x to -z here
    robot.set_base_ori(np.array([np.pi / 2, np.pi / 2, np.pi / 2]))
    model = robot.get_model()
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    axes = data.body("robot3_base").xmat.reshape(3, 3)
    np.testing.assert_allclose(axes, [[0, 0, 1], [0, -1, 0], [1, 0, 0]], atol=1e-12)  # columns: x, y, z
    with pytest.raises(assembler.AssemblerError, match="expected 3 finite angles"):
        robot.set_base_ori(np.array([0.0, np.nan, 0.0]))


def test_home_keyframe_holds_the_init_pose(robot: assembler.RobotModel) -> None:
    model = robot.get_model()
    assert [model.key(i).name for i in range(model.nkey)] == ["home"]  # the file's key is replaced
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    np.testing.assert_allclose(data.qpos, [0.5, -0.5])
    np.testing.assert_allclose(data.ctrl, [0.5, -0.5])  # position actuators hold the pose


def test_init_qpos_of_the_wrong_length_points_at_the_spec(write, two_link: Path) -> None:  # type: ignore[no-untyped-def]
    two_link.write_text("name: TwoLink\nmjcf: twolink.xml\ninit_qpos: [0.5]\n")
    (cls,) = assembler.register_specs(two_link)
    with pytest.raises(
        SpecError,
        match=r"twolink.yaml:3:12: init_qpos: expected 2 values \(one per joint: shoulder, elbow\), got 1$",
    ):
        cls(idn=0).check()


def test_missing_mjcf_file_points_at_the_spec(write) -> None:  # type: ignore[no-untyped-def]
    spec = write("s/robot.yaml", "name: Ghost\nmjcf: nowhere.xml\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError, match=r"robot.yaml:2:7: mjcf: MJCF file not found: .*nowhere.xml$"):
        cls(idn=0).check()


def test_mjcf_that_mujoco_rejects_is_reported_with_both_files(write) -> None:  # type: ignore[no-untyped-def]
    write(
        "s/bad.xml",
        "<mujoco><worldbody><body name='b'><joint name='j' type='hinj'/></body></worldbody></mujoco>",
    )
    spec = write("s/robot.yaml", "name: Bad\nmjcf: bad.xml\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(
        MjcfError, match=r"robot.yaml:2:7: mjcf: .*bad.xml:1: MuJoCo cannot read it: invalid keyword: 'hinj'"
    ):
        cls(idn=0).check()


def test_two_root_bodies_are_refused(write) -> None:  # type: ignore[no-untyped-def]
    write("s/two.xml", "<mujoco><worldbody><body name='a'/><body name='b'/></worldbody></mujoco>")
    (cls,) = assembler.register_specs(write("s/robot.yaml", "name: Two\nmjcf: two.xml\n"))
    with pytest.raises(MjcfError, match=r"expected exactly one body in <worldbody>, found 2 \('a', 'b'\)"):
        cls(idn=0).check()


def test_compile_errors_name_the_spec(write) -> None:  # type: ignore[no-untyped-def]
    write(
        "s/massless.xml",
        "<mujoco><worldbody><body name='b'><joint name='j'/></body></worldbody></mujoco>",
    )
    (cls,) = assembler.register_specs(write("s/robot.yaml", "name: Massless\nmjcf: massless.xml\n"))
    with pytest.raises(
        MjcfError,
        match=r"robot.yaml:1:1: robot 'Massless': MuJoCo cannot compile the assembly: mass and inertia",
    ):
        cls(idn=0).get_model()
