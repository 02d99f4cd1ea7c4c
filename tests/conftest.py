"""Shared fixtures: tiny inline MJCF and YAML written to real files, and an isolated registry."""

from __future__ import annotations

import textwrap
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

from assembler.registry import REGISTERED_ROBOTS

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

TWO_LINK_SPEC = """\
name: TwoLink
mjcf: twolink.xml
init_qpos: [0.5, -0.5]
"""


@pytest.fixture(autouse=True)
def isolated_registry() -> Iterator[None]:
    """Each test sees the shipped robots; whatever it registers is removed afterwards."""
    snapshot = dict(REGISTERED_ROBOTS)
    yield
    REGISTERED_ROBOTS.clear()
    REGISTERED_ROBOTS.update(snapshot)


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
