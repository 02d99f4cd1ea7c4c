"""A site material given through a default (dm-control's Kinova ``common.xml``) survives the assembly."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np

import assembler

COMMON = """\
<mujoco>
  <asset>
    <material name="red" rgba="1 0 0 1"/>
    <material name="blue" rgba="0 0 1 1"/>
  </asset>
  <default>
    <site material="red" size="0.01"/>
    <default class="marker">
      <site material="blue"/>
    </default>
  </default>
</mujoco>
"""

ARM = """\
<mujoco model="kinovaish">
  <include file="common.xml"/>
  <worldbody>
    <body name="base">
      <geom type="box" size="0.05 0.05 0.05" mass="1"/>
      <site name="base_site"/>
      <body name="link" pos="0 0 0.1">
        <joint name="j1" axis="0 0 1" range="-1 5.46288124"/>
        <geom type="box" size="0.05 0.05 0.05" mass="1"/>
        <site name="marker_site" class="marker"/>
        <body name="right_hand" pos="0 0 0.1"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def test_site_materials_from_an_included_default_reach_the_compiled_robot(
    write: Callable[[str, str], Path],
) -> None:
    write("arm/common.xml", COMMON)
    direct = mujoco.MjModel.from_xml_path(str(write("arm/arm.xml", ARM)))
    (cls,) = assembler.register_specs(write("arm/arm.yaml", "name: Kinovaish\nmjcf: arm.xml\n"))

    model = cls(idn=0).get_model(cache=False)

    materials = {model.site(s).name: model.mat(model.site_matid[s]).name for s in range(model.nsite)}
    assert materials == {"robot0_base_site": "robot0_red", "robot0_marker_site": "robot0_blue"}
    assert [direct.mat(m).name for m in direct.site_matid] == ["red", "blue"]


def test_a_part_read_again_for_its_site_materials_keeps_every_digit(
    write: Callable[[str, str], Path],
) -> None:
    """Jaco's joint_2 range was cut to MuJoCo's six written digits (5.46288 for 5.462881) by the re-read."""
    write("arm/common.xml", COMMON)
    direct = mujoco.MjModel.from_xml_path(str(write("arm/arm.xml", ARM)))
    (cls,) = assembler.register_specs(write("arm/arm.yaml", "name: Kinovaish\nmjcf: arm.xml\n"))

    model = cls(idn=0).get_model(cache=False)

    # 15 significant digits, as every model we write (emit.XML_SIGNIFICANT_DIGITS); six lost 1e-6
    np.testing.assert_allclose(model.joint("robot0_j1").range, direct.joint("j1").range, rtol=1e-13, atol=0)
