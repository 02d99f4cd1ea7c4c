"""Shared fixtures: tiny inline MJCF and YAML written to real files, and an isolated registry."""

from __future__ import annotations

import signal
import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from assembler.registry.lookup import REGISTERED_BASES, REGISTERED_GRIPPERS, REGISTERED_ROBOTS

TWO_LINK_MJCF = """\
<mujoco model="twolink">
  <compiler angle="radian" autolimits="true"/>
  <default>
    <default class="arm">
      <joint damping="3"/>
      <default class="wrist">
        <joint armature="2"/>
      </default>
    </default>
  </default>
  <worldbody>
    <body name="base" pos="0 0 0.1">
      <camera name="robotview" pos="1 0 0.5" xyaxes="0 1 0 -0.4 0 1"/>
      <site name="right_center" size="0.01"/>
      <geom name="base_col" type="cylinder" size="0.05 0.05"/>
      <body name="link1" pos="0 0 0.1" childclass="wrist">
        <joint name="shoulder" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <geom name="link1_vis" type="capsule" fromto="0 0 0 0.3 0 0" size="0.031" group="1"
              contype="0" conaffinity="0" rgba="1 1 1 1"/>
        <body name="link2" pos="0.3 0 0">
          <joint name="elbow" axis="0 1 0" range="-2 2" class="arm" frictionloss="0.25"/>
          <geom name="link2_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.025" mass="0.5"/>
          <body name="right_hand" pos="0.3 0 0"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="act_shoulder" joint="shoulder" kp="200" dampratio="1" ctrlrange="-3 3"/>
    <position name="act_elbow" joint="elbow" kp="100" dampratio="1" ctrlrange="-2 2"/>
  </actuator>
  <keyframe>
    <key name="file_home" qpos="0.3 0.4"/>
  </keyframe>
</mujoco>
"""
"""Two hinge joints: 'shoulder' gets armature 2 and damping 3 through childclass 'wrist' nested
in 'arm'; 'elbow' gets damping 3 from its explicit class 'arm' and a literal frictionloss."""

TETRAHEDRON_OBJ = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
"""A 0.1 m tetrahedron as OBJ text: the smallest mesh MuJoCo compiles, for tests that need a mesh file."""

INCLUDING_ARM_MJCF = """\
<mujoco model="arm">
  <compiler angle="radian" meshdir="meshes"/>
  <asset><mesh name="tet" file="tet.obj"/></asset>
  <worldbody>
    <body name="base">
      <body name="link1" pos="0 0 0.1">
        <joint name="joint1" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="mesh" mesh="tet" mass="1"/>
        <body name="right_hand" pos="0 0 0.1"/>
      </body>
    </body>
  </worldbody>
  <include file="actuators.xml"/>
</mujoco>
"""
"""One joint, a mesh (meshes/tet.obj) and an ``<include>``d actuators.xml: every kind of file a build
reads, for tests of what is read and written."""

MESH_ARM_MJCF = """\
<mujoco model="meshy">
  <compiler angle="radian" meshdir="meshes"/>
  <asset><mesh name="tet" file="tet.obj"/><mesh name="tet_big" file="tet.obj" scale="2 2 2"/></asset>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="cylinder" size="0.05 0.05" mass="2"/>
      <body name="link1" pos="0 0 0.1">
        <joint name="joint1" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="mesh" mesh="tet" mass="1"/>
        <body name="link2" pos="0 0 0.1">
          <joint name="joint2" axis="0 1 0" range="-2 2"/>
          <geom name="link2_col" type="capsule" fromto="0 0 0 0.2 0 0" size="0.02" mass="0.5"/>
          <geom name="link2_vis" type="mesh" mesh="tet_big" group="1" contype="0" conaffinity="0" mass="0"/>
          <body name="right_hand" pos="0.2 0 0"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="act1" joint="joint1" kp="50" ctrlrange="-3 3"/>
    <position name="act2" joint="joint2" kp="50" ctrlrange="-2 2"/>
  </actuator>
</mujoco>
"""
"""Two joints and one OBJ mesh (meshes/tet.obj, :data:`TETRAHEDRON_OBJ`) used twice, at two scales:
for tests of what the cache and the mesh store keep."""

TWO_LINK_SPEC = """\
name: TwoLink
mjcf: twolink.xml
init_qpos: [0.5, -0.5]
"""


def use_private_cache(folder: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """Point the model cache (and its mesh store) at ``folder``, the cache on and no size limit
    inherited from the environment: for tests of the cache itself."""
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(folder))
    monkeypatch.delenv("ASSEMBLER_NO_CACHE", raising=False)
    monkeypatch.delenv("ASSEMBLER_CACHE_MAX_BYTES", raising=False)
    return folder


@pytest.fixture(scope="session", autouse=True)
def ctrl_c_as_at_a_terminal() -> None:
    """Ctrl-C reaches the commands the tests start, as it does at a terminal. A test run started in the
    background of a non-interactive shell (``pytest &``) ignores SIGINT, and every process it starts
    would inherit that (an ignored signal stays ignored across exec): the tests of Ctrl-C then see
    commands that cannot be interrupted."""
    if signal.getsignal(signal.SIGINT) == signal.SIG_IGN:
        signal.signal(signal.SIGINT, signal.default_int_handler)


@pytest.fixture(autouse=True)
def isolated_cache(tmp_path_factory: pytest.TempPathFactory, monkeypatch: pytest.MonkeyPatch) -> None:
    """The compiled-model cache of the test session lives in a temporary folder, never the user's."""
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path_factory.getbasetemp() / "model-cache"))


@pytest.fixture(autouse=True)
def isolated_registry() -> Iterator[None]:
    """Each test sees the shipped specs; whatever it registers is removed afterwards."""
    tables = (REGISTERED_ROBOTS, REGISTERED_BASES, REGISTERED_GRIPPERS)
    snapshots = [dict(table) for table in tables]
    yield
    for table, snapshot in zip(tables, snapshots, strict=True):
        table.clear()
        table.update(snapshot)


@pytest.fixture
def write(tmp_path: Path) -> Callable[[str, str], Path]:
    """Write dedented text to a file below the test's temporary folder and return its path."""

    def write_file(relative: str, text: str) -> Path:
        path = tmp_path / relative
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(textwrap.dedent(text))
        return path

    return write_file


@pytest.fixture
def two_link(write: Callable[[str, str], Path]) -> Path:
    """A spec folder with the two-link robot (spec + MJCF); returns the spec file."""
    write("robots/twolink.xml", TWO_LINK_MJCF)
    return write("robots/twolink.yaml", TWO_LINK_SPEC)


MOUNT_MJCF = """\
<mujoco model="mount">
  <worldbody>
    <body name="base" pos="0 0 -0.5">
      <geom name="post_col" type="cylinder" size="0.1 0.25" pos="0 0 -0.25" mass="10"/>
    </body>
  </worldbody>
</mujoco>
"""

MOBILE_MJCF = """\
<mujoco model="mobile">
  <worldbody>
    <body name="base">
      <joint name="joint_mobile_forward" type="slide" axis="1 0 0" limited="false"/>
      <joint name="joint_mobile_yaw" type="hinge" axis="0 0 1" limited="false"/>
      <geom name="chassis_col" type="box" size="0.3 0.2 0.1" pos="0 0 0.1" mass="40"/>
      <body name="lift" pos="0 0 0.2">
        <joint name="joint_torso_height" type="slide" axis="0 0 1" range="0 0.3"/>
        <geom name="lift_col" type="box" size="0.05 0.05 0.2" pos="0 0 0.2" mass="5"/>
        <body name="support" pos="0 0 0.4">
          <site name="center" size="0.01"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <velocity name="actuator_mobile_forward" joint="joint_mobile_forward" kv="1000" ctrlrange="-1 1"/>
    <velocity name="actuator_mobile_yaw" joint="joint_mobile_yaw" kv="1000" ctrlrange="-1 1"/>
    <position name="actuator_torso" joint="joint_torso_height" kp="5000" dampratio="1" ctrlrange="0 0.3"/>
  </actuator>
  <sensor>
    <jointpos name="torso_pos" joint="joint_torso_height"/>
  </sensor>
</mujoco>
"""

LEGGED_MJCF = """\
<mujoco model="legged">
  <worldbody>
    <body name="trunk" pos="0 0 0.4">
      <freejoint name="root"/>
      <geom name="trunk_col" type="box" size="0.3 0.15 0.05" mass="10"/>
      <body name="support" pos="0 0 0.05"><site name="center" size="0.01"/></body>
      <body name="fr_thigh" pos="0.25 -0.15 0">
        <joint name="fr_hip_leg" axis="0 1 0" range="-1 1"/>
        <geom name="fr_col" type="capsule" fromto="0 0 0 0 0 -0.35" size="0.03" mass="1"/>
      </body>
      <body name="fl_thigh" pos="0.25 0.15 0">
        <joint name="fl_hip_leg" axis="0 1 0" range="-1 1"/>
        <geom name="fl_col" type="capsule" fromto="0 0 0 0 0 -0.35" size="0.03" mass="1"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="fr_act" joint="fr_hip_leg" kp="100"/>
    <motor name="fl_act" joint="fl_hip_leg"/>
  </actuator>
</mujoco>
"""

NULL_BASE_MJCF = """\
<mujoco model="null_base">
  <worldbody>
    <body name="support"><site name="center" size="0.01"/></body>
  </worldbody>
</mujoco>
"""

GRIPPER_MJCF = """\
<mujoco model="pinch">
  <compiler autolimits="true"/>
  <option timestep="0.001"/>
  <worldbody>
    <body name="pinch_root" pos="0 0 0.01" quat="0.7071068 0 0 -0.7071068">
      <site name="ft_frame" size="0.01"/>
      <geom name="palm_col" type="box" size="0.02 0.04 0.02" pos="0 0 0.02" mass="0.3"/>
      <body name="finger" pos="0 0 0.05">
        <joint name="finger_joint" type="slide" axis="0 1 0" range="0 0.03"/>
        <geom name="finger_pad_col" type="box" size="0.005 0.005 0.02" mass="0.05"/>
      </body>
      <body name="eef" pos="0 0 0.1" quat="0 1 0 0">
        <site name="grip_site" size="0.005"/>
        <site name="grip_site_cylinder" type="cylinder" size="0.005 1"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="finger_act" joint="finger_joint" kp="100" ctrlrange="0 0.03"/>
  </actuator>
  <sensor>
    <force name="force_ee" site="ft_frame"/>
    <torque name="torque_ee" site="ft_frame"/>
  </sensor>
</mujoco>
"""

PART_SPECS = {
    "mount.yaml": "kind: base\nname: TestMount\ntype: mount\nmjcf: mount.xml\ntop_offset: [0, 0, -0.01]\nhorizontal_radius: 0.3\n",
    "mobile.yaml": "kind: base\nname: TestMobile\ntype: mobile\nmjcf: mobile.xml\ninit_qpos: [0, 0, 0.2]\nhorizontal_radius: 0.4\n",
    "legged.yaml": "kind: base\nname: TestLegs\ntype: legged\nmjcf: legged.xml\ninit_qpos: [0.3, -0.3]\n",
    "null_base.yaml": "kind: base\nname: TestNull\ntype: null\nmjcf: null_base.xml\n",
    "pinch.yaml": (
        "kind: gripper\nname: TestPinch\nmjcf: pinch.xml\ninit_qpos: [0.02]\n"
        "important_geoms:\n  right_fingerpad: [finger_pad_col]\n"
    ),
}


@pytest.fixture
def parts(write: Callable[[str, str], Path], two_link: Path) -> Path:
    """Register a mount, a mobile base, a legged base, a null base and a gripper (plus TwoLink)."""
    import assembler

    for name, text in {
        "mount.xml": MOUNT_MJCF,
        "mobile.xml": MOBILE_MJCF,
        "legged.xml": LEGGED_MJCF,
        "null_base.xml": NULL_BASE_MJCF,
        "pinch.xml": GRIPPER_MJCF,
        **PART_SPECS,
    }.items():
        write(f"parts/{name}", text)
    assembler.register_specs(two_link.parent, two_link.parent.parent / "parts")
    return two_link.parent.parent / "parts"
