"""``assembler new``: a spec for a model file that validates and builds as written, every guess
commented, nothing in the model file changed. Real files and real compiles; the published robots
are in tests/corpus."""

from __future__ import annotations

import os
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.files.paths import allowing
from assembler.registry.catalog import register_specs
from tests.conftest import TETRAHEDRON_OBJ, TWO_LINK_MJCF

NO_ACTUATORS = TWO_LINK_MJCF.split("  <actuator>")[0] + "</mujoco>\n"
"""The two-link arm without its actuators (as dm_control's Jaco arm comes)."""

OUT_OF_RANGE = TWO_LINK_MJCF.replace('range="-2 2"', 'range="0.5 2"')
"""The elbow's range excludes 0, MuJoCo's qpos0."""


def _new(model: Path, spec: Path, *flags: str) -> int:
    return main(["new", str(model), "-o", str(spec), *flags])


def test_new_writes_a_spec_that_validates_and_builds_as_written(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/twolink.xml", TWO_LINK_MJCF)
    before = model.read_bytes()
    spec = model.with_name("twolink.yaml")
    assert _new(model, spec) == 0
    assert capsys.readouterr().out == (
        f"wrote {spec}: robot Twolink (validated and compiled); check each 'guess:' and settle each "
        "'decide:' comment\n"
    )
    fields = yaml.safe_load(spec.read_text())
    assert fields["mjcf"] == "twolink.xml"
    assert fields["eef_bodies"] == {"right": "right_hand"}
    assert fields["joint_groups"] == {"right": ["shoulder", "elbow"]}
    (cls,) = register_specs(spec)
    robot = assembler.assemble(cls.__name__)
    assert robot.get_model().njnt == 2 + 2  # the arm's two joints and the default gripper's two
    assert model.read_bytes() == before


def test_every_field_new_writes_has_a_comment_saying_why(write: Callable[[str, str], Path]) -> None:
    model = write("robots/twolink.xml", TWO_LINK_MJCF)
    spec = model.with_name("twolink.yaml")
    assert _new(model, spec) == 0
    lines = spec.read_text().splitlines()
    fields = [
        i for i, line in enumerate(lines) if line and not line[0].isspace() and not line.startswith("#")
    ]
    uncommented = [lines[i] for i in fields if not lines[i - 1].startswith("#")]
    assert uncommented == [
        "description: twolink from twolink.xml, as `assembler new` read it.",
        "mjcf: twolink.xml",
    ]


def test_new_refuses_to_replace_an_existing_spec_unless_forced(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/twolink.xml", TWO_LINK_MJCF)
    spec = write("robots/twolink.yaml", "name: Mine\nmjcf: twolink.xml\n")
    assert _new(model, spec) == 1
    assert capsys.readouterr().err.strip().splitlines() == [
        f"{spec}: exists; keep it, or give --force to replace it"
    ]
    assert spec.read_text() == "name: Mine\nmjcf: twolink.xml\n"
    assert _new(model, spec, "--force") == 0
    assert "name: Twolink" in spec.read_text()


def test_a_file_without_actuators_gets_servos_with_guessed_torque_limits_marked_to_decide(
    write: Callable[[str, str], Path],
) -> None:
    model = write("robots/bare.xml", NO_ACTUATORS)
    spec = model.with_name("bare.yaml")
    assert _new(model, spec) == 0
    text = spec.read_text()
    assert "# decide: no effort limit in the file for shoulder, elbow" in text
    (cls,) = register_specs(spec)
    compiled = assembler.create_robot(cls.__name__).get_model()
    assert compiled.nu == 2
    shoulder = compiled.actuator("robot0_shoulder")
    # the bound: twice the torque gravity exerts with everything beyond the joint stretched out, rounded up
    vendor = mujoco.MjModel.from_xml_path(str(model))
    data = mujoco.MjData(vendor)
    mujoco.mj_kinematics(vendor, data)
    bodies = [vendor.body(name).id for name in ("link1", "link2", "right_hand")]
    load = sum(vendor.body_mass[b] * np.linalg.norm(data.xipos[b] - data.xanchor[0]) for b in bodies)
    low, high = shoulder.forcerange
    assert low == -high and 2 * 9.81 * load <= high <= 1.1 * 2 * 9.81 * load
    assert compiled.actuator_biastype[shoulder.id] == mujoco.mjtBias.mjBIAS_AFFINE  # a position servo
    assert compiled.actuator_gainprm[shoulder.id, 0] == pytest.approx(high / 0.05, rel=1e-2)


def test_a_robot_new_wrote_holds_its_home_pose_for_a_second_with_ctrl_at_home(
    write: Callable[[str, str], Path],
) -> None:
    model = write("robots/bare.xml", NO_ACTUATORS)
    spec = model.with_name("bare.yaml")
    assert _new(model, spec) == 0
    (cls,) = register_specs(spec)
    assert np.max(_drift(assembler.create_robot(cls.__name__).get_model())) < 0.1


def _drift(model: mujoco.MjModel, seconds: float = 1.0) -> np.ndarray:
    """Per joint, the largest distance from home over ``seconds`` with each servo's target at home."""
    data = mujoco.MjData(model)
    if model.nkey:
        mujoco.mj_resetDataKeyframe(model, data, 0)
    home = data.qpos.copy()
    data.ctrl[:] = home[model.jnt_qposadr[model.actuator_trnid[:, 0]]]
    worst = np.zeros(model.nq)
    for _ in range(round(seconds / model.opt.timestep)):
        mujoco.mj_step(model, data)
        worst = np.maximum(worst, np.abs(data.qpos - home))
    return worst


def test_a_zero_pose_outside_a_joint_range_is_moved_to_the_middle_of_the_range(
    write: Callable[[str, str], Path],
) -> None:
    model = write("robots/twolink.xml", OUT_OF_RANGE)
    spec = model.with_name("twolink.yaml")
    assert _new(model, spec) == 0
    assert yaml.safe_load(spec.read_text())["init_qpos"] == [0.0, 1.25]
    assert "# guess: elbow moved to the middle of their range: qpos0 lies outside it" in spec.read_text()


def test_a_file_named_like_a_hand_becomes_a_gripper_spec(write: Callable[[str, str], Path]) -> None:
    model = write("hands/my_hand.xml", TWO_LINK_MJCF)
    spec = model.with_name("my_hand.yaml")
    assert _new(model, spec) == 0
    fields = yaml.safe_load(spec.read_text())
    assert (fields["kind"], fields["name"], fields["eef_body"]) == ("gripper", "Twolink", "base")
    assert fields["actions"]["dimensions"] == [{"actuators": ["act_shoulder"]}, {"actuators": ["act_elbow"]}]
    (cls,) = register_specs(spec)
    assert assembler.create_gripper(cls.__name__).compile_alone().nu == 2


def test_a_model_file_mujoco_refuses_is_one_line_naming_it(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/broken.xml", TWO_LINK_MJCF.replace('joint="elbow"', 'joint="nope"'))
    assert _new(model, model.with_name("broken.yaml")) == 1
    (line,) = capsys.readouterr().err.strip().splitlines()
    assert line.startswith(f"{model}:") and "nope" in line
    assert not model.with_name("broken.yaml").exists()


ARM_ALONE = "<mujoco>\n" + TWO_LINK_MJCF.split("<worldbody>\n")[1].split("  </worldbody>")[0] + "</mujoco>\n"
"""The two-link arm's bodies alone, as a file a task scene includes inside its <worldbody>."""

TASK_SCENE = (
    TWO_LINK_MJCF.split("  <worldbody>")[0]
    + """  <include file="task_shared.xml"/>
  <worldbody>
    <geom name="floor0" type="plane" size="1 1 1"/>
    <light name="light0" pos="0 0 3" dir="0 0 -1"/>
    <body name="mocap0" mocap="true" pos="0.6 0 0.4"><geom type="box" size="0.01 0.01 0.01" contype="0" conaffinity="0"/></body>
    <include file="task_arm.xml"/>
    <body name="table0" pos="1 0 0.2"><geom type="box" size="0.3 0.3 0.2"/></body>
  </worldbody>
  <sensor><framepos name="target_pos" objtype="body" objname="table0"/></sensor>
"""
    + TWO_LINK_MJCF.split("  </worldbody>\n")[1]
)
"""The two-link arm inside a task scene as gymnasium-robotics writes one (Fetch's reach.xml): a floor,
a light, a table and a mocap body around the arm's <include>, and in an included file the weld that
holds the hand to the mocap body."""

TASK_SHARED = '<mujoco><equality><weld body1="mocap0" body2="right_hand"/></equality></mujoco>\n'


def _task_scene(write: Callable[[str, str], Path]) -> Path:
    write("robots/task_arm.xml", ARM_ALONE)
    write("robots/task_shared.xml", TASK_SHARED)
    return write("robots/reach.xml", TASK_SCENE)


def test_a_task_scene_is_cut_down_to_its_robot_by_the_fixes_new_writes(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = _task_scene(write)
    before = {path: path.read_bytes() for path in model.parent.glob("*.xml")}
    spec = model.with_name("reach.yaml")
    assert _new(model, spec) == 0, capsys.readouterr().err
    fixes = yaml.safe_load(spec.read_text())["mjcf_fixes"]
    assert [(fix["element"], fix["where"]) for fix in fixes] == [
        ("geom", {"name": "floor0"}),
        ("light", {"name": "light0"}),
        ("body", {"name": "mocap0"}),
        ("body", {"name": "table0"}),
        ("weld", {"body1": "mocap0"}),
        ("framepos", {"name": "target_pos"}),
    ]
    assert all(fix["delete"] is True and fix["why"] for fix in fixes)
    text = spec.read_text()
    for comment in (
        "  # geom floor0 (reach.xml:13), beside the robot in <worldbody>",
        "  # body mocap0 (reach.xml:15), beside the robot in <worldbody>",
        "  # unnamed weld in <equality> (task_shared.xml:1)",
    ):
        assert comment in text
    (cls,) = register_specs(spec)
    robot = assembler.create_robot(cls.__name__, idn=0).get_model()
    alone = mujoco.MjModel.from_xml_string(TWO_LINK_MJCF)
    assert [robot.body(b).name for b in range(robot.nbody)] == [
        "world",
        *("robot0_" + alone.body(b).name for b in range(1, alone.nbody)),
    ]
    assert (robot.neq, robot.nmocap, robot.nsensor, robot.nlight) == (0, 0, 0, 0)
    assert {path: path.read_bytes() for path in model.parent.glob("*.xml")} == before


def test_a_scene_element_no_selection_picks_out_alone_is_named_for_the_user(
    write: Callable[[str, str], Path],
) -> None:
    twin = '<body name="table0" pos="1 0 0.2">'
    model = _task_scene(write)
    # an unnamed world geom written exactly as a geom of the arm: deleting it would delete the arm's
    model.write_text(model.read_text().replace(twin, '<geom type="cylinder" size="0.05 0.05"/>\n    ' + twin))
    write("robots/task_arm.xml", ARM_ALONE.replace('name="base_col" ', ""))
    spec = model.with_name("reach.yaml")
    assert _new(model, spec) == 0
    assert (
        "# decide: unnamed geom (reach.xml:17) should go too, but no where: selects them" in spec.read_text()
    )


def test_a_hand_placed_in_a_scene_is_reset_to_the_arm_it_is_mounted_on(
    write: Callable[[str, str], Path],
) -> None:
    far = TWO_LINK_MJCF.replace('<body name="base" pos="0 0 0.1">', '<body name="base" pos="1 1.25 0.15">')
    model = write("hands/reach_hand.xml", far)
    spec = model.with_name("reach_hand.yaml")
    assert _new(model, spec) == 0
    assert yaml.safe_load(spec.read_text())["root_pose"] == "reset"
    assert "# guess: the file places the root body base 1.61 m from the origin" in spec.read_text()
    (cls,) = register_specs(spec)
    compiled = assembler.create_gripper(cls.__name__, idn=0).compile_alone()
    assert np.allclose(compiled.body("gripper0_base").pos, 0)


def test_a_name_a_registered_spec_has_is_not_taken_again(write: Callable[[str, str], Path]) -> None:
    model = write("robots/panda.xml", TWO_LINK_MJCF.replace('model="twolink"', 'model="panda"'))
    spec = model.with_name("panda.yaml")
    assert _new(model, spec) == 0
    assert yaml.safe_load(spec.read_text())["name"] == "PandaArm"  # robosuite's Panda has a shipped spec
    assert (
        "# guess: Panda is the name of a registered spec or of a robosuite class already" in spec.read_text()
    )


MIMIC_URDF = """\
<robot name="pincer_arm">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <link name="link1"><inertial><origin xyz="0 0 0.2"/><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 0.2"/><geometry><cylinder radius="0.03" length="0.4"/></geometry></collision></link>
  <link name="left_finger"><inertial><mass value="0.1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="right_finger"><inertial><mass value="0.1"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <joint name="joint1" type="revolute"><parent link="base"/><child link="link1"/><axis xyz="0 1 0"/>
    <limit lower="-2" upper="2" effort="40" velocity="2"/></joint>
  <joint name="left_finger_joint" type="prismatic"><parent link="link1"/><child link="left_finger"/>
    <origin xyz="0 0.02 0.4"/><axis xyz="0 1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.1"/></joint>
  <joint name="right_finger_joint" type="prismatic"><parent link="link1"/><child link="right_finger"/>
    <origin xyz="0 -0.02 0.4"/><axis xyz="0 -1 0"/><limit lower="0" upper="0.04" effort="20" velocity="0.1"/>
    <mimic joint="left_finger_joint" multiplier="1" offset="0"/></joint>
</robot>
"""
"""A one-joint arm with a jaw of two fingers, the second following the first (URDF <mimic>)."""


def test_a_urdf_jaw_is_left_out_of_the_arm_and_its_mimic_follower_gets_no_servo(
    write: Callable[[str, str], Path],
) -> None:
    model = write("robots/pincer_arm.urdf", MIMIC_URDF)
    spec = model.with_name("pincer_arm.yaml")
    assert _new(model, spec) == 0
    fields = yaml.safe_load(spec.read_text())
    assert fields["joint_groups"] == {"right": ["joint1"]}
    assert fields["default_grippers"] == {"right": None}
    assert "# guess: right_finger_joint follow another joint (URDF <mimic>): no servo" in spec.read_text()
    (cls,) = register_specs(spec)
    compiled = assembler.create_robot(cls.__name__).get_model()
    motors = [compiled.actuator(a).name for a in range(compiled.nu)]
    assert motors == ["robot0_joint1", "robot0_left_finger_joint"]
    assert compiled.actuator("robot0_joint1").forcerange.tolist() == [-40.0, 40.0]  # the URDF's effort


MESH_URDF = MIMIC_URDF.replace(
    '<collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision>',
    '<collision><geometry><mesh filename="package://arm_description/meshes/tet.obj"/></geometry></collision>',
)
"""The arm with a mesh named through a ROS package that no package root holds (pybullet's xArm6)."""


def test_a_package_beside_the_urdf_is_declared_beside_the_spec_new_writes(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    write("robots/arm_description/meshes/tet.obj", TETRAHEDRON_OBJ)
    model = write("robots/pincer_arm.urdf", MESH_URDF)
    spec = model.with_name("pincer_arm.yaml")
    assert _new(model, spec) == 0
    marker = model.with_name("robot-assembler.toml")
    assert capsys.readouterr().out.startswith(
        f"wrote {spec}: robot PincerArm and {marker} (validated and compiled)"
    )
    assert marker.read_text().splitlines()[-1] == 'packages = ["arm_description"]'
    (cls,) = register_specs(spec)
    assert assembler.create_robot(cls.__name__).get_model().nmesh == 1  # found without ROS_PACKAGE_PATH


def test_a_package_beside_a_urdf_in_a_spec_repository_is_the_entry_to_add_to_it(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    declaration = write("lab/robot-assembler.toml", 'allow = ["vendor"]\n')
    write("lab/vendor/arm_description/meshes/tet.obj", TETRAHEDRON_OBJ)
    model = write("lab/vendor/pincer_arm.urdf", MESH_URDF)
    spec = declaration.parent / "specs" / "pincer_arm.yaml"
    spec.parent.mkdir()
    assert _new(model, spec) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[1] == (
        f"to do: package://arm_description is the folder {model.parent / 'arm_description'} beside the URDF: "
        f'add "vendor/arm_description" to packages in {declaration}'
    )
    assert "ROS_PACKAGE_PATH" not in os.environ  # new found it for its own check only
    declaration.write_text('allow = ["vendor"]\npackages = ["vendor/arm_description"]\n')  # as it says
    (cls,) = register_specs(spec)
    assert assembler.create_robot(cls.__name__).get_model().nmesh == 1


def test_a_package_beside_a_urdf_no_declaration_can_name_is_the_ros_package_path_to_export(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    folder = write("vendor/arm_description/meshes/tet.obj", TETRAHEDRON_OBJ).parents[1]
    model = write("vendor/pincer_arm.urdf", MESH_URDF)
    spec = write("lab/keep.txt", "").with_name("pincer_arm.yaml")  # outside the URDF's folders, as pybullet's
    assert main(["--allow-path", str(model.parent), "new", str(model), "-o", str(spec)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[1:] == [
        f"to do: package://arm_description is the folder {folder} beside the URDF: set ROS_PACKAGE_PATH to "
        "hold it (a spec repository may name only folders inside it)",
        f"  export ROS_PACKAGE_PATH={folder}",
    ]
    assert not spec.with_name("robot-assembler.toml").exists() and "ROS_PACKAGE_PATH" not in os.environ
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(folder))  # as printed
    with allowing([model.parent]):
        (cls,) = register_specs(spec)
        assert assembler.create_robot(cls.__name__).get_model().nmesh == 1


def test_a_package_beside_a_urdf_of_an_installed_python_package_is_exported_even_inside_a_checkout(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    """A venv inside the spec repository (CI's, many a lab's ``.venv``): the spec names the URDF as
    package://, so the declaration would name this machine's install; new says to export the folder."""
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    write("lab/robot-assembler.toml", "")
    write("lab/.venv/site/vendor_robots/__init__.py", "")
    folder = write("lab/.venv/site/vendor_robots/arm_description/meshes/tet.obj", TETRAHEDRON_OBJ).parents[1]
    model = write("lab/.venv/site/vendor_robots/pincer_arm.urdf", MESH_URDF)
    monkeypatch.syspath_prepend(str(folder.parents[1]))
    spec = write("lab/specs/keep.txt", "").with_name("pincer_arm.yaml")
    assert _new(model, spec) == 0
    assert capsys.readouterr().out.splitlines()[1:] == [
        f"to do: package://arm_description is the folder {folder} beside the URDF: set ROS_PACKAGE_PATH to "
        "hold it (a spec repository may name only folders inside it)",
        f"  export ROS_PACKAGE_PATH={folder}",
    ]
    assert "urdf: package://vendor_robots/pincer_arm.urdf" in spec.read_text()
    monkeypatch.setenv("ROS_PACKAGE_PATH", str(folder))  # as printed
    (cls,) = register_specs(spec)
    assert assembler.create_robot(cls.__name__).get_model().nmesh == 1


@pytest.mark.parametrize("generic", ["physics", "Robot", "MuJoCo Model"])
def test_a_generic_model_name_gives_way_to_the_file_name(
    write: Callable[[str, str], Path], generic: str
) -> None:
    # pybullet's pr2_gripper.urdf is <robot name="physics">
    model = write("robots/pr2_arm.xml", TWO_LINK_MJCF.replace('model="twolink"', f'model="{generic}"'))
    spec = model.with_name("pr2_arm.yaml")
    assert _new(model, spec) == 0
    assert yaml.safe_load(spec.read_text())["name"] == "Pr2Arm"


def test_a_scene_whose_included_files_name_assets_from_the_main_files_folder_is_read_as_mujoco_reads_it(
    write: Callable[[str, str], Path],
) -> None:
    # metaworld's sawyer_xyz/*.xml includes ../objects/assets/*.xml, whose meshes are named from the main
    # file's folder (../objects/meshes/...), as MuJoCo resolves them; the other arm of the scene sits in a
    # file of its own (gym-aloha's vx300s_right.xml), which the cut empties
    write("objects/meshes/link.obj", TETRAHEDRON_OBJ)
    write(
        "objects/assets/deps.xml",
        '<mujocoinclude><asset><mesh name="link" file="../objects/meshes/link.obj"/></asset></mujocoinclude>',
    )
    arm = TWO_LINK_MJCF.split("<worldbody>")[1].split("</worldbody>")[0]
    twin = arm.replace('name="', 'name="twin_').replace('joint="', 'joint="twin_')
    write("objects/assets/twin.xml", f"<mujocoinclude>{twin}</mujocoinclude>")
    scene = TWO_LINK_MJCF.split("<worldbody>")[0].replace('<mujoco model="twolink">', "<mujoco>")
    scene += '<include file="../objects/assets/deps.xml"/>\n<worldbody>' + arm.replace(
        '<geom name="base_col" type="cylinder" size="0.05 0.05"/>',
        '<geom name="base_col" type="mesh" mesh="link"/>',
    )
    scene += '<include file="../objects/assets/twin.xml"/>\n</worldbody>\n</mujoco>\n'
    model = write("tasks/sawyer_task.xml", scene)
    spec = model.with_name("sawyer_task.yaml")
    with allowing([model.parent.parent]):
        assert _new(model, spec, "--allow-path", str(model.parent.parent)) == 0
    text = spec.read_text()
    assert "# decide: the file also holds twin_" in text
    assert "name: Tasks" in text  # a task scene is named after its folder


UNBALANCED_URDF = """<robot name="wobbly">
  <link name="base"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial></link>
  <link name="arm"><inertial><mass value="1"/><inertia ixx="0.001" iyy="0.001" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.1 0.1 0.1"/></geometry></collision></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="arm"/><axis xyz="0 0 1"/><limit lower="-1" upper="1" effort="5" velocity="1"/></joint>
</robot>
"""
"""A link whose inertia violates A + B >= C, which MuJoCo reads only with balanceinertia."""

SINGULAR = UNBALANCED_URDF.replace(
    'ixx="0.001" iyy="0.001" izz="0.01" ixy="0" ixz="0" iyz="0"',
    'ixx="0.001" iyy="0.001" izz="0.001" ixy="0.001" ixz="0.001" iyz="0.001"',
)
"""ANYmal C's ``hatch``: products that make the inertia singular, refused even with balanceinertia."""


def test_an_inertia_made_valid_is_said_with_both_values_and_strict_refuses_it(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/wobbly.urdf", UNBALANCED_URDF)
    spec = model.with_name("wobbly.yaml")
    assert _new(model, spec, "--strict") == 1
    err = capsys.readouterr().err
    assert "inertia must satisfy A + B >= C" in err and "--strict: balance_inertia would repair it" in err
    assert not spec.exists()
    assert _new(model, spec) == 0
    text = spec.read_text()
    assert (
        "# guess: link 'arm': full inertia (0.001, 0.001, 0.01, 0, 0, 0) violates A + B >= C: made diagonal "
        "(0.004,\n#   0.004, 0.004), isotropic at the mean of its principal moments"
    ) in text
    assert "balance_inertia: true" in text and "new --strict refuses the file" in text
    (cls,) = register_specs(spec)
    compiled = assembler.create_robot(cls.__name__).get_model()
    assert compiled.body("robot0_arm").inertia == pytest.approx([0.004] * 3)


def test_an_inertia_mujoco_refuses_even_balanced_is_refused_with_its_reason(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/wobbly.urdf", SINGULAR)
    assert _new(model, model.with_name("wobbly.yaml")) == 1
    assert "must have positive eigenvalues' in fullinertia Element name 'arm'" in capsys.readouterr().err


def test_a_gripper_spec_new_wrote_builds_alone(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    # docs/add-your-robot.md: assembler build hand.yaml, as for a robot spec
    hand = TWO_LINK_MJCF.replace('model="twolink"', 'model="claw_hand"')
    model = write("robots/claw_hand.xml", hand)
    spec = model.with_name("claw_hand.yaml")
    assert _new(model, spec) == 0 and "kind: gripper" in spec.read_text()
    # its links reach along +x of its root (pybullet's PR2 gripper too): the mount on an arm is said
    assert "# decide: the fingers reach along +x of the root body base, robosuite's grippers along +z" in (
        spec.read_text()
    )
    out = spec.with_name("claw_hand_built.xml")
    assert main(["build", str(spec), "-o", str(out)]) == 0
    built = mujoco.MjModel.from_xml_path(str(out))
    assert built.njnt == 2 and built.nu == 2
