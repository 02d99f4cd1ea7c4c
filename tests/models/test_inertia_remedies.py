"""An inertia MuJoCo refuses (A + B < C) is refused at the spec's line, naming the spec's remedy."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.errors import MjcfError

URDF = """\
<robot name="arm">
  <link name="base">
    <inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <link name="link1">
    <inertial><mass value="1"/><inertia ixx="1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
  </link>
  <joint name="j1" type="revolute">
    <parent link="base"/><child link="link1"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="10" velocity="1"/>
  </joint>
</robot>
"""

MJCF = """\
<mujoco>
  <worldbody>
    <body name="base">
      <body name="link1">
        <inertial pos="0 0 0" mass="1" diaginertia="1 0.1 0.1"/>
        <joint name="j1" axis="0 0 1" range="-1 1"/>
        <body name="right_hand"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""

BALANCE_MJCF = """\
mjcf_fixes:
  - element: compiler
    set: {balanceinertia: "true"}
    why: link1's inertia violates A + B >= C in the vendor's file
"""


def test_a_urdf_inertia_mujoco_refuses_names_balance_inertia_at_the_specs_line(
    write: Callable[[str, str], Path],
) -> None:
    write("arm.urdf", URDF)
    (cls,) = assembler.register_specs(
        write("arm.yaml", "name: Arm\nurdf: arm.urdf\neef_bodies: {right: link1}\n")
    )
    with pytest.raises(
        MjcfError,
        match=r"arm.yaml:2:7: urdf: .*arm.urdf: the inertia of link link1 violates A \+ B >= C, which MuJoCo "
        r"refuses; set balance_inertia: true in the spec",
    ):
        cls(idn=0).check()


def test_balance_inertia_makes_the_urdf_robot_build(write: Callable[[str, str], Path]) -> None:
    write("arm.urdf", URDF)
    spec = "name: Arm\nurdf: arm.urdf\neef_bodies: {right: link1}\nbalance_inertia: true\n"
    (cls,) = assembler.register_specs(write("arm.yaml", spec))
    model = cls(idn=0).get_model(cache=False)
    assert model.body("robot0_link1").inertia.tolist() == pytest.approx([0.4, 0.4, 0.4])


def test_an_mjcf_inertia_mujoco_refuses_names_the_repair_a_spec_declares(
    write: Callable[[str, str], Path],
) -> None:
    write("arm.xml", MJCF)
    (cls,) = assembler.register_specs(write("arm.yaml", "name: ArmM\nmjcf: arm.xml\n"))
    with pytest.raises(
        MjcfError,
        match=r"arm.yaml:2:7: mjcf: .*arm.xml:4: MuJoCo refuses it: inertia must satisfy A \+ B >= C.*; correct "
        r"the <inertial>, or declare the repair in the spec: mjcf_fixes: \[\{element: compiler, "
        r"set: \{balanceinertia: 'true'\}, why: ...\}\]$",
    ):
        cls(idn=0).check()
    (cls,) = assembler.register_specs(write("arm.yaml", "name: ArmM\nmjcf: arm.xml\n" + BALANCE_MJCF))
    assert cls(idn=0).get_model(cache=False).body("robot0_link1").inertia.tolist() == pytest.approx([0.4] * 3)
