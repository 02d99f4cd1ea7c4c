"""Each trap of MuJoCo's URDF import, shown on a small URDF package written by the test, and handled.

The traps (MuJoCo issues #1432, #1176, #3527 and the forum's DAE questions): ``package://`` mesh
paths reduced to a bare name, visual geoms discarded, the fixed base link fused into the world,
``<mimic>`` dropped, DAE meshes unreadable, and no actuators. Each test first shows what MuJoCo's
own import does with the same file, where that is the trap, then what the assembler makes of it.
"""

from __future__ import annotations

import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.cli import main
from assembler.errors import AssemblerError, AssemblerWarning, MissingPackageError, MjcfError
from assembler.files.extras import install_command
from assembler.files.paths import allowing, shipped_specs_dir
from assembler.models import RobotModel
from assembler.urdf import load_urdf
from assembler.urdf.document import read_urdf
from assembler.urdf.mesh_formats import converted_dir, converter_available, importable
from assembler.urdf.packages import package_folders
from assembler.urdf.postprocess import add_mimics
from tests.urdf.fixtures import ARM_URDF, line_of, write_package, write_stl

STL_LINE = line_of(ARM_URDF, "cube.stl")
DAE_LINE = line_of(ARM_URDF, "cube.dae")
MIMIC_JOINT_LINE = line_of(ARM_URDF, '<joint name="finger_b_joint"')

NEEDS_CONVERTER = pytest.mark.skipif(
    not (converter_available() and importable("collada")),
    reason='the test URDF\'s COLLADA mesh needs trimesh and pycollada: pip install "robot-assembler[urdf]"',
)

SPEC = """\
name: MyArm
urdf: {urdf}
eef_bodies: {{right: tool}}
actuators:
  - {{match: shoulder, kp: 50, kv: 5}}
  - {{match: "finger_*", kp: 200, kv: 5}}
  - {{match: spin, type: velocity, kv: 1}}
init_qpos: [0.3, 0.0, 0.02, -0.01]
"""


@pytest.fixture
def package(tmp_path: Path) -> Path:
    """The URDF of the test package (tmp/ros/my_arm/urdf/my_arm.urdf)."""
    return write_package(tmp_path / "ros")


def _robot(tmp_path: Path, urdf: str, text: str = SPEC) -> RobotModel:
    spec = tmp_path / "arm.yaml"
    spec.write_text(text.format(urdf=urdf))
    (cls,) = assembler.register_specs(spec)
    robot = cls(idn=0)
    assert isinstance(robot, RobotModel)
    robot.check()  # parts read their file when first used: read it now, as the tests expect
    return robot


def _direct_import(text: str) -> mujoco.MjSpec:
    return mujoco.MjSpec.from_string(text)


def _load(urdf: Path) -> None:
    with allowing([urdf.parent.parent.parent]):  # as a spec in that folder would
        load_urdf(str(urdf))


def _mesh_files(robot: RobotModel) -> dict[str, Path]:
    return {Path(mesh.file).name: Path(mesh.file) for mesh in robot.prepared_mjspec.meshes}


@NEEDS_CONVERTER
def test_package_uri_meshes_are_found_through_the_package_its_repository_declares(
    tmp_path: Path, package: Path
) -> None:
    with pytest.raises(ValueError, match="Error opening file"):  # the trap: the path is stripped
        _direct_import(ARM_URDF).compile()
    robot = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf")
    files = _mesh_files(robot)
    assert files["cube.stl"] == package.parent.parent / "meshes" / "cube.stl"
    (converted,) = [name for name in files if name != "cube.stl"]
    assert converted.startswith("cube-") and converted.endswith(".obj")
    assert robot.get_model().nmesh == 2


@NEEDS_CONVERTER
@pytest.mark.parametrize("variable", ["ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH"])
def test_package_uri_meshes_are_found_through_ros_environment_variables(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, variable: str
) -> None:
    # The URDF lies outside its package, so only the environment can say where my_arm is.
    installed = tmp_path / "prefix" / "share"
    write_package(installed, declare=False)
    (tmp_path / "arm.urdf").write_text(ARM_URDF)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    monkeypatch.delenv("AMENT_PREFIX_PATH", raising=False)
    with pytest.raises(MjcfError) as caught:
        _robot(tmp_path, "arm.urdf")
    assert (
        str(caught.value)
        .splitlines()[0]
        .endswith(
            f"arm.urdf:{STL_LINE}: mesh package://my_arm/meshes/cube.stl: package 'my_arm' not found (searched the "
            "packages its spec repository declares, ROS_PACKAGE_PATH, AMENT_PREFIX_PATH and the share/ folders "
            "of this Python environment); declare its folder in packages of the spec repository's "
            "robot-assembler.toml (README: Spec repositories), or set ROS_PACKAGE_PATH or AMENT_PREFIX_PATH "
            "to where it is"
        )
    )
    monkeypatch.setenv(variable, str(installed if variable == "ROS_PACKAGE_PATH" else installed.parent))
    robot = _robot(tmp_path, "arm.urdf")
    assert _mesh_files(robot)["cube.stl"] == (installed / "my_arm" / "meshes" / "cube.stl").resolve()


@NEEDS_CONVERTER
def test_a_mesh_uri_that_leaves_its_package_is_refused(tmp_path: Path, package: Path) -> None:
    (tmp_path / "secret.stl").write_bytes((package.parent.parent / "meshes" / "cube.stl").read_bytes())
    package.write_text(
        ARM_URDF.replace("package://my_arm/meshes/cube.stl", "package://my_arm/../../secret.stl")
    )
    with pytest.raises(
        MjcfError, match=rf"my_arm.urdf:{STL_LINE}: mesh .*secret.stl is outside the folders a spec may read"
    ):
        _load(package)


@NEEDS_CONVERTER
def test_visual_geoms_are_kept_in_group_1_without_contacts(tmp_path: Path, package: Path) -> None:
    text = ARM_URDF.replace("package://my_arm", str(package.parent.parent)).replace("cube.dae", "cube.stl")
    direct = _direct_import(text).compile()  # the trap: discardvisual is on for URDF
    assert direct.ngeom == 2
    model = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf").get_model()
    visual = [g for g in range(model.ngeom) if model.geom_group[g] == 1]
    collision = [g for g in range(model.ngeom) if model.geom_group[g] == 0]
    assert [model.geom(g).name for g in visual] == ["robot0_base_link_visual", "robot0_link1_visual"]
    assert [model.geom(g).name for g in collision] == ["robot0_base_link_collision", "robot0_link1_collision"]
    assert all(model.geom_contype[g] == 0 and model.geom_conaffinity[g] == 0 for g in visual)
    assert all(model.geom_contype[g] == 1 and model.geom_conaffinity[g] == 1 for g in collision)


@NEEDS_CONVERTER
def test_the_fixed_base_link_stays_a_body_with_its_mass(tmp_path: Path, package: Path) -> None:
    text = ARM_URDF.replace("package://my_arm", str(package.parent.parent)).replace("cube.dae", "cube.stl")
    direct = _direct_import(text).compile()  # the trap: fusestatic merges base_link into the world
    assert "base_link" not in [direct.body(b).name for b in range(direct.nbody)]
    robot = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf")
    model = robot.get_model()
    assert robot.root_body == "robot0_base_link"
    assert model.body("robot0_base_link").mass[0] == pytest.approx(2.0)
    assert model.body("robot0_tool").parentid[0] == model.body("robot0_spinner").id  # fixed joints stay too


@NEEDS_CONVERTER
def test_mimic_becomes_a_joint_equality_that_holds_in_simulation(tmp_path: Path, package: Path) -> None:
    model = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf").get_model()
    assert model.neq == 1 and model.eq_type[0] == mujoco.mjtEq.mjEQ_JOINT
    assert model.joint(model.eq_obj1id[0]).name == "robot0_finger_b_joint"
    np.testing.assert_allclose(model.eq_data[0, :5], [0.01, -1.0, 0.0, 0.0, 0.0])
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    data.ctrl[model.actuator("robot0_finger_a_joint").id] = 0.035
    for _ in range(1000):
        mujoco.mj_step(model, data)
    leader, follower = (data.joint(f"robot0_finger_{x}_joint").qpos[0] for x in "ab")
    assert leader == pytest.approx(0.035, abs=2e-3)
    assert follower == pytest.approx(-leader + 0.01, abs=1e-3)
    assert "robot0_finger_b_joint" not in [model.actuator(a).name for a in range(model.nu)]  # globs skip it


@NEEDS_CONVERTER
def test_mimic_is_added_when_mujoco_drops_it(package: Path) -> None:
    # MuJoCo before 4.0 dropped <mimic> silently; the assembler adds what is missing, never twice.
    document = read_urdf(package, [package.parent], package.read_bytes())
    spec = mujoco.MjSpec.from_string(document.text)
    for equality in list(spec.equalities):
        spec.delete(equality)
    add_mimics(spec, document.mimics, "my_arm.urdf")
    add_mimics(spec, document.mimics, "my_arm.urdf")
    assert [(e.name1, e.name2, list(e.data[:2])) for e in spec.equalities] == [
        ("finger_b_joint", "finger_a_joint", [0.01, -1.0])
    ]


@NEEDS_CONVERTER
@pytest.mark.parametrize(
    ("leader", "why"),
    [
        ("tool_joint", "'tool_joint' is not a revolute, continuous or prismatic joint"),
        ("finger_b_joint", "the joint mimics itself"),
    ],
)
def test_a_mimic_mujoco_ignores_is_ignored_with_a_note_naming_its_line(
    tmp_path: Path, leader: str, why: str
) -> None:
    # Talos' grippers mimic on fixed joints: MuJoCo's import ignores such a <mimic>, so does the read
    text = ARM_URDF.replace('<mimic joint="finger_a_joint"', f'<mimic joint="{leader}"')
    urdf = write_package(tmp_path / "ros", urdf=text)
    with pytest.warns(AssemblerWarning) as caught, allowing([urdf.parent.parent.parent]):
        source = load_urdf(str(urdf))
    following = "" if leader == "finger_b_joint" else f" (following '{leader}')"
    line = (
        f"my_arm.urdf:{MIMIC_JOINT_LINE}: <mimic> of joint 'finger_b_joint'{following} is ignored, as "
        f"MuJoCo's URDF import ignores it: {why}"
    )
    assert [str(w.message) for w in caught if str(w.message).endswith(line)]
    assert [note for note in source.notes if note.endswith(line)]
    assert source.new_spec().compile().neq == 0


@NEEDS_CONVERTER
def test_a_dae_mesh_is_converted_to_obj_in_metres(tmp_path: Path, package: Path) -> None:
    meshes = package.parent.parent / "meshes"
    (meshes / "visual_cube.dae").write_bytes((meshes / "cube.dae").read_bytes())  # a stem of its own
    with pytest.raises(ValueError):  # the trap: MuJoCo reads no COLLADA
        _direct_import(
            ARM_URDF.replace("package://my_arm", str(package.parent.parent))
            .replace("cube.dae", "visual_cube.dae")
            .replace(
                '<robot name="my_arm">',
                '<robot name="my_arm"><mujoco><compiler discardvisual="false"/></mujoco>',
            )
        ).compile()
    robot = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf")
    source = robot.source
    assert "1 mesh file(s) converted to OBJ in" in source.notes[-1]
    model = robot.get_model()
    mesh = [
        m for m in range(model.nmesh) if Path(robot.prepared_mjspec.meshes[m].file).parent == converted_dir()
    ]
    vertices = model.mesh_vert[
        model.mesh_vertadr[mesh[0]] : model.mesh_vertadr[mesh[0]] + model.mesh_vertnum[mesh[0]]
    ]
    assert np.ptp(vertices, axis=0) == pytest.approx([0.1, 0.1, 0.1])  # 100 mm, not 100 m


TWIN_MESHES_URDF = """<robot name="twins">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <visual><geometry><mesh filename="meshes/visual/link.stl"/></geometry></visual>
    <collision><geometry><mesh filename="meshes/collision/link.stl"/></geometry></collision>
  </link>
</robot>
"""
"""A visual and a collision mesh in two files with one name, as vendors' packages lay them out."""


def test_two_mesh_files_with_one_name_stay_two_meshes(tmp_path: Path) -> None:
    # The trap, before MuJoCo 4.0: its import names a mesh after its file's stem and kept one
    # mesh per name, so the collision geom silently got the visual mesh.
    write_stl(tmp_path / "meshes" / "visual" / "link.stl", edge=0.1)
    write_stl(tmp_path / "meshes" / "collision" / "link.stl", edge=0.3)
    _write(tmp_path / "twins.urdf", TWIN_MESHES_URDF)
    robot = _robot(tmp_path, "twins.urdf", "name: Twins\nurdf: {urdf}\neef_bodies: {{right: base}}\n")
    model = robot.get_model()
    sizes = {}
    for name in ("robot0_base_visual", "robot0_base_collision"):
        mesh = model.geom(name).dataid[0]
        start, count = model.mesh_vertadr[mesh], model.mesh_vertnum[mesh]
        sizes[name] = np.ptp(model.mesh_vert[start : start + count], axis=0)[0]
    assert sizes == pytest.approx({"robot0_base_visual": 0.1, "robot0_base_collision": 0.3})
    assert "1 mesh file(s) whose name another mesh has copied under a distinct name" in robot.source.notes[-1]


@NEEDS_CONVERTER
def test_an_unreadable_mesh_is_reported_once_with_what_to_do(tmp_path: Path, package: Path) -> None:
    (package.parent.parent / "meshes" / "broken.dae").write_text("<COLLADA><library_geometries>")
    package.write_text(ARM_URDF.replace("cube.dae", "broken.dae").replace("cube.stl", "broken.dae"))
    with pytest.raises(MjcfError) as caught:
        _load(package)
    lines = str(caught.value).splitlines()
    assert len(lines) == 1 and lines[0] == (
        f"{package}:{STL_LINE}: {package.parent.parent / 'meshes' / 'broken.dae'}: not well-formed XML: "
        "no element found: line 1, column 29"
    )


def test_without_the_converters_a_dae_mesh_says_what_to_install(
    tmp_path: Path, package: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setitem(sys.modules, "trimesh", None)  # as if the urdf extra were not installed
    monkeypatch.setitem(sys.modules, "collada", None)
    with pytest.raises(MjcfError) as caught:
        _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf")
    (line,) = str(caught.value).splitlines()
    assert line.endswith(
        "cube.dae: MuJoCo cannot read .dae meshes (only STL, OBJ, MSH) and trimesh and pycollada to convert "
        f"it are not installed; {install_command('urdf')}, which brings trimesh and pycollada, or convert "
        "it to STL/OBJ yourself"
    )
    assert "arm.yaml:2:7: urdf: " in line and f"my_arm.urdf:{DAE_LINE}: " in line


@NEEDS_CONVERTER
def test_limits_efforts_and_velocities_become_ranges_that_hold_in_simulation(
    tmp_path: Path, package: Path
) -> None:
    robot = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf")
    model = robot.get_model()
    shoulder, spin = model.joint("robot0_shoulder"), model.joint("robot0_spin")
    assert shoulder.limited[0] == 1 and list(shoulder.range) == [-1.0, 1.0]
    assert list(model.jnt_actfrcrange[shoulder.id]) == [-5.0, 5.0] and spin.limited[0] == 0
    servo, velocity = model.actuator("robot0_shoulder"), model.actuator("robot0_spin")
    assert list(servo.ctrlrange) == [-1.0, 1.0] and list(servo.forcerange) == [-5.0, 5.0]
    assert velocity.ctrllimited[0] == 0  # a continuous joint without <limit velocity>
    records = {r.name: r for r in robot.actuator_table}
    assert records["shoulder"].values["ctrlrange"] == ("[-1, 1]", "joint range")
    assert records["shoulder"].values["forcerange"] == ("[-5, 5]", "joint effort limit")
    assert records["finger_a_joint"].values["ctrlrange"] == ("[0, 0.04]", "joint range")
    data = mujoco.MjData(model)
    data.ctrl[servo.id] = 1.0
    data.qfrc_applied[shoulder.dofadr[0]] = 50.0  # ten times the servo's force: only the limit stops it
    for _ in range(1000):
        mujoco.mj_step(model, data)
    assert data.joint("robot0_shoulder").qpos[0] == pytest.approx(1.0, abs=0.02)


@NEEDS_CONVERTER
def test_a_velocity_servo_takes_the_urdf_velocity_limit_as_its_range(tmp_path: Path, package: Path) -> None:
    text = SPEC.replace("{{match: shoulder, kp: 50, kv: 5}}", "{{match: shoulder, type: velocity, kv: 3}}")
    robot = _robot(tmp_path, "ros/my_arm/urdf/my_arm.urdf", text)
    actuator = robot.get_model().actuator("robot0_shoulder")
    assert list(actuator.ctrlrange) == [-2.0, 2.0]
    assert {r.name: r for r in robot.actuator_table}["shoulder"].values["ctrlrange"][
        1
    ] == "urdf velocity limit"


@NEEDS_CONVERTER
def test_the_spec_names_a_ros_package_with_package_uri(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    write_package(tmp_path / "prefix" / "share", declare=False)
    monkeypatch.setenv("AMENT_PREFIX_PATH", str(tmp_path / "prefix"))
    robot = _robot(tmp_path, "package://my_arm/urdf/my_arm.urdf")
    assert robot.source.path == (tmp_path / "prefix" / "share" / "my_arm" / "urdf" / "my_arm.urdf").resolve()
    monkeypatch.delenv("AMENT_PREFIX_PATH")
    with pytest.raises(
        MissingPackageError, match=r"package://my_arm/urdf/my_arm.urdf: package 'my_arm' not found"
    ):
        _robot(tmp_path, "package://my_arm/urdf/my_arm.urdf")


def test_a_spec_that_extends_one_with_the_other_kind_of_file_replaces_the_file(
    tmp_path: Path, package: Path
) -> None:
    text = "name: MyArmU\nextends: Finch6\nurdf: ros/my_arm/urdf/my_arm.urdf\ninit_qpos: null\neef_bodies: {right: tool}\n"
    (spec_class,) = assembler.register_specs(_write(tmp_path / "child.yaml", text))
    assert spec_class.spec.mjcf is None and spec_class.spec.urdf == str(package)
    # and back: an MJCF child of a URDF spec drops the parent's URDF-only balance_inertia
    parent = (
        "name: MyArmB\nurdf: ros/my_arm/urdf/my_arm.urdf\nbalance_inertia: true\neef_bodies: {right: tool}\n"
    )
    child = "name: MyArmM\nextends: MyArmB\nmjcf: arm.xml\n"
    _write(tmp_path / "arm.xml", '<mujoco><worldbody><body name="tool"/></worldbody></mujoco>')
    classes = assembler.register_specs(
        _write(tmp_path / "b.yaml", parent), _write(tmp_path / "m.yaml", child)
    )
    child_spec = classes[1].spec
    assert (child_spec.urdf, child_spec.balance_inertia, child_spec.mjcf) == (
        None,
        False,
        str(tmp_path / "arm.xml"),
    )


@NEEDS_CONVERTER
def test_a_base_and_a_gripper_can_come_from_urdf(tmp_path: Path, package: Path) -> None:
    _write(tmp_path / "post.urdf", POST_URDF)
    base_text = "kind: base\nname: UrdfPost\ntype: mount\nurdf: post.urdf\n"
    gripper_text = (
        "kind: gripper\nname: UrdfFingers\nurdf: ros/my_arm/urdf/my_arm.urdf\neef_body: tool\n"
        "important_sites: {}\nimportant_sensors: {}\n"
        'actuators: [{match: "finger_*", kp: 100, kv: 2}]\ninit_qpos: [0, 0, 0.02, -0.01]\n'
    )
    assembler.register_specs(
        _write(tmp_path / "post.yaml", base_text), _write(tmp_path / "fingers.yaml", gripper_text)
    )
    robot = assembler.assemble("Sparrow7", idn=0, base="UrdfPost", grippers={"right": "UrdfFingers"})
    model = robot.get_model()
    assert model.body("fixed_mount0_post").mass[0] == pytest.approx(8.0)
    assert model.actuator("gripper0_right_finger_a_joint").ctrlrange[1] == pytest.approx(0.04)
    assert model.neq == 1 and robot.grippers["right"].dof == 1


def test_a_urdf_that_is_not_a_robot_is_refused_in_one_line(tmp_path: Path) -> None:
    urdf = _write(tmp_path / "a" / "b" / "not.urdf", "<mujoco/>")
    with pytest.raises(
        AssemblerError, match=r"not.urdf: not a URDF file: the root element is <mujoco>, expected <robot>$"
    ):
        _load(urdf)


POST_URDF = """<robot name="post">
  <link name="post">
    <inertial><mass value="8"/><inertia ixx="0.1" iyy="0.1" izz="0.05" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 -0.25"/><geometry><cylinder radius="0.1" length="0.5"/></geometry></collision>
  </link>
</robot>
"""


def _write(path: Path, text: str) -> Path:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    return path


@pytest.mark.skipif(
    bool(package_folders("example-robot-data")),
    reason="example-robot-data is installed: this shows validate and list without the urdf extra",
)
def test_without_the_urdf_extra_the_shipped_urdf_specs_are_unchecked_not_failed(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["validate", str(shipped_specs_dir() / "urdf")]) == 0
    out, err = capsys.readouterr()
    unchecked, because = out.splitlines()
    assert unchecked.startswith("6 spec(s) valid but not checked against their model file: ")
    assert because == (
        "    because: package 'example-robot-data' not found (searched ROS_PACKAGE_PATH, AMENT_PREFIX_PATH "
        f"and the share/ folders of this Python environment); install it: {install_command('urdf')}"
    )
    assert main(["list", "bases"]) == 0
    (go2,) = [line for line in capsys.readouterr().out.splitlines() if line.startswith("Go2 ")]
    assert "? (example-robot-data not installed)" in go2
