"""``add_free_joint``: a URDF cannot declare a floating base, so a spec gives its root body a free
joint (as MuJoCo Menagerie's Go2 adds a ``<freejoint/>`` to the URDF's base): the robot falls and
stands on its own; a legged base hands it to the robot's root, as an MJCF base's free joint.

The URDF here has no meshes, so these tests run without the urdf extra.
"""

from __future__ import annotations

from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import AssemblerError

LEGS_URDF = """<robot name="legs">
  <link name="trunk">
    <inertial><mass value="10"/><inertia ixx="0.1" iyy="0.2" izz="0.2" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.5 0.3 0.1"/></geometry></collision>
  </link>
  <link name="top"/>
  <joint name="top_joint" type="fixed"><parent link="trunk"/><child link="top"/><origin xyz="0 0 0.05"/></joint>
  <link name="leg">
    <inertial><origin xyz="0 0 -0.15"/><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 -0.15"/><geometry><cylinder radius="0.03" length="0.3"/></geometry></collision>
  </link>
  <joint name="hip" type="revolute">
    <parent link="trunk"/><child link="leg"/><origin xyz="0.2 0 -0.05"/><axis xyz="0 1 0"/>
    <limit lower="-1" upper="1" effort="50" velocity="5"/>
  </joint>
</robot>
"""
"""A trunk (10 kg) with one leg on a hinge: no floating joint, as every URDF."""


def _register(tmp_path: Path, spec: str) -> type[assembler.models.PartModel]:
    (tmp_path / "legs.urdf").write_text(LEGS_URDF)
    (tmp_path / "spec.yaml").write_text(spec)
    (cls,) = assembler.register_specs(tmp_path / "spec.yaml")
    return cls


def _free_joints(model: mujoco.MjModel) -> list[str]:
    free = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    return [model.body(model.jnt_bodyid[j]).name for j in free]


def test_a_urdf_robot_with_add_free_joint_falls_freely(tmp_path: Path) -> None:
    _register(tmp_path, "name: Legs\nurdf: legs.urdf\neef_bodies: {right: top}\nadd_free_joint: true\n")
    robot = assembler.create_robot("Legs", idn=0)
    model = robot.get_model()
    assert _free_joints(model) == ["robot0_trunk"] and robot.joints == ["robot0_hip"]  # not counted
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    start = data.body("robot0_trunk").xpos[2]
    for _ in range(int(round(0.5 / model.opt.timestep))):
        mujoco.mj_step(model, data)
    fallen = start - data.body("robot0_trunk").xpos[2]
    assert fallen == pytest.approx(0.5 * 9.81 * 0.5**2, rel=0.02)  # free fall: nothing holds it


def test_without_add_free_joint_the_urdf_root_is_welded(tmp_path: Path) -> None:
    _register(tmp_path, "name: Legs\nurdf: legs.urdf\neef_bodies: {right: top}\n")
    model = assembler.create_robot("Legs", idn=0).get_model()
    assert _free_joints(model) == [] and model.nq == 1


def test_a_legged_base_from_urdf_hands_its_free_joint_to_the_robot_root(tmp_path: Path) -> None:
    _register(
        tmp_path,
        "kind: base\nname: LegsBase\ntype: legged\nurdf: legs.urdf\nsupport_body: top\nadd_free_joint: true\n"
        "actuators: [{match: hip, kp: 100}]\n",
    )
    model = assembler.assemble("Sparrow7", idn=0, base="LegsBase").get_model()
    assert _free_joints(model) == ["robot0_base"]  # the robot's root, as for an MJCF legged base
    assert model.body("leg0_trunk").parentid[0] == model.body("robot0_base").id


INVALID = [
    (
        "name: Legs\nurdf: legs.urdf\neef_bodies: {right: top}\nadd_free_joint: true\nremove_free_joint: true\n",
        "spec.yaml:1:1: give remove_free_joint or add_free_joint, not both",
    ),
    (
        "kind: base\nname: Legged\ntype: legged\nmjcf: legged.xml\nsupport_body: support\nadd_free_joint: true\n",
        "spec.yaml:6:17: add_free_joint: the root body 'trunk' already has joints (root); a free joint must be "
        "its only joint (a file with a free joint floats already: leave add_free_joint out)",
    ),
]


@pytest.mark.parametrize(("spec", "expected"), INVALID)
def test_add_free_joint_mistakes_are_one_line_at_the_spec(tmp_path: Path, spec: str, expected: str) -> None:
    (tmp_path / "legged.xml").write_text(
        '<mujoco><worldbody><body name="trunk"><freejoint name="root"/><geom size="0.1" mass="1"/>'
        '<body name="support"/></body></worldbody></mujoco>'
    )
    with pytest.raises(AssemblerError) as caught:
        _register(tmp_path, spec)(idn=0).check()  # the schema refuses the first, the file the second
    (line,) = str(caught.value).splitlines()
    assert line.endswith(expected)


def test_a_floating_urdf_robot_keeps_its_home_pose_values(tmp_path: Path) -> None:
    _register(
        tmp_path,
        "name: Legs\nurdf: legs.urdf\neef_bodies: {right: top}\nadd_free_joint: true\ninit_qpos: [0.5]\n"
        "actuators: [{match: hip, kp: 100}]\n",
    )
    model = assembler.create_robot("Legs", idn=0).get_model()
    np.testing.assert_allclose(model.key("home").qpos[7:], [0.5])  # after the free joint's 7 values
    assert model.key("home").ctrl[0] == pytest.approx(0.5)
