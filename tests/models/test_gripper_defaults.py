"""A gripper validates without robosuite's grip sites and sensors, which robosuite's bridge adds;
where its file has them, they are its important sites and sensors without a word in the spec."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import assembler
from tests.conftest import GRIPPER_MJCF

BARE_HAND = """\
<mujoco model="bare">
  <worldbody>
    <body name="palm">
      <geom name="palm_col" type="box" size="0.02 0.04 0.02" mass="0.3"/>
      <body name="finger" pos="0 0 0.05">
        <joint name="curl" type="hinge" axis="1 0 0" range="0 1.5"/>
        <geom name="finger_col" type="box" size="0.005 0.005 0.02" mass="0.05"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""


def test_a_gripper_without_robosuites_grip_sites_and_sensors_validates_as_written(
    write: Callable[[str, str], Path],
) -> None:
    write("bare.xml", BARE_HAND)
    (cls,) = assembler.register_specs(
        write("bare.yaml", "kind: gripper\nname: Bare\nmjcf: bare.xml\neef_body: palm\n")
    )
    gripper = cls(idn=0)
    gripper.check()
    assert (gripper.important_sites, gripper.important_sensors) == ({}, {})
    assert gripper.compile_alone().nsite == 0


def test_a_gripper_with_them_has_them_as_important_sites_and_sensors(
    write: Callable[[str, str], Path],
) -> None:
    write("pinch.xml", GRIPPER_MJCF)
    (cls,) = assembler.register_specs(write("pinch.yaml", "kind: gripper\nname: Pinch\nmjcf: pinch.xml\n"))
    gripper = cls(idn=0)
    assert gripper.important_sites == {
        "grip_site": "gripper0_grip_site",
        "grip_cylinder": "gripper0_grip_site_cylinder",
    }
    assert gripper.important_sensors == {"force_ee": "gripper0_force_ee", "torque_ee": "gripper0_torque_ee"}
