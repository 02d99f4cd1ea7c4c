"""``assembler new`` on wheeled robots: a cart with wheels and no arm is a mobile base spec an arm
goes on (not an arm of wheels with a gripper on a wheel); a cart carrying an arm is a robot whose
wheels are its base's joints, never its arm's. Real URDF files, real compiles and simulation."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.registry.catalog import register_specs


def _wheel(side: str, x: float, y: float) -> str:
    return f"""
  <link name="{side}_wheel">
    <inertial><mass value="0.5"/><inertia ixx="0.001" iyy="0.001" izz="0.001" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin rpy="1.5708 0 0"/><geometry><cylinder radius="0.1" length="0.04"/></geometry></collision>
  </link>
  <joint name="{side}_wheel_joint" type="continuous">
    <parent link="chassis"/><child link="{side}_wheel"/>
    <origin xyz="{x} {y} 0"/><axis xyz="0 1 0"/><limit effort="5" velocity="20"/>
  </joint>"""


def _arm_link(
    joint: str, parent: str, link: str, mass: float, length: float, origin: str, axis: str, effort: float
) -> str:
    """A box link ``length`` long along z, on a revolute joint of range -2..2 rad."""
    return f"""
  <link name="{link}">
    <inertial><mass value="{mass}"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><origin xyz="0 0 {length / 2}"/><geometry><box size="0.05 0.05 {length}"/></geometry></collision>
  </link>
  <joint name="{joint}" type="revolute">
    <parent link="{parent}"/><child link="{link}"/><origin xyz="{origin}"/><axis xyz="{axis}"/>
    <limit lower="-2" upper="2" effort="{effort}" velocity="2"/>
  </joint>"""


def _cart(arm: bool) -> str:
    """A chassis on four wheels whose lowest point is 0.1 m below the chassis's origin; with ``arm``,
    three revolute joints on top of it."""
    links = "".join(
        _arm_link(*link)
        for link in (
            ("joint1", "chassis", "shoulder", 1.0, 0.3, "0 0 0.05", "0 0 1", 20),
            ("joint2", "shoulder", "upper", 1.0, 0.3, "0 0 0.3", "0 1 0", 20),
            ("joint3", "upper", "fore", 0.5, 0.2, "0 0 0.3", "0 1 0", 10),
        )
    )
    wheels = "".join(_wheel(side, x, y) for side, x, y in WHEELS)
    return f"""<?xml version="1.0"?>
<robot name="{"cart_arm" if arm else "cart"}">
  <link name="chassis">
    <inertial><mass value="10"/><inertia ixx="0.1" iyy="0.1" izz="0.1" ixy="0" ixz="0" iyz="0"/></inertial>
    <collision><geometry><box size="0.6 0.4 0.1"/></geometry></collision>
  </link>{wheels}{links if arm else ""}
</robot>
"""


WHEELS = (
    ("front_left", 0.25, 0.25),
    ("front_right", 0.25, -0.25),
    ("rear_left", -0.25, 0.25),
    ("rear_right", -0.25, -0.25),
)


def _written(write: Callable[[str, str], Path], arm: bool) -> tuple[dict, Path]:
    model = write(f"carts/{'cart_arm' if arm else 'cart'}.urdf", _cart(arm))
    spec = model.with_suffix(".yaml")
    assert main(["new", str(model), "-o", str(spec)]) == 0
    return yaml.safe_load(spec.read_text()), spec


def test_a_cart_with_wheels_and_no_arm_is_written_as_a_mobile_base_an_arm_stands_on(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    fields, spec = _written(write, arm=False)
    assert "base Cart (validated and compiled)" in capsys.readouterr().out
    assert (fields["kind"], fields["type"], fields["support_body"]) == ("base", "mobile", "chassis")
    assert fields["bottom_offset"] == [0.0, 0.0, -0.1]  # the wheels' lowest point, 0.1 m below the chassis
    assert fields["top_offset"] == [0.0, 0.0, 0.05]  # the chassis's top face
    assert fields["horizontal_radius"] == pytest.approx(
        np.hypot(0.35, 0.27), abs=1e-3
    )  # a wheel's far corner
    wheels = [f"{side}_wheel_joint" for side, _, _ in WHEELS]
    assert fields["joint_groups"] == {"base": wheels}
    assert [(a["match"], a["type"]) for a in fields["actuators"]] == [(w, "velocity") for w in wheels]
    alone = spec.with_name("cart.xml")
    assert main(["build", str(spec), "-o", str(alone)]) == 0  # a base spec builds alone, as a gripper's does
    assert mujoco.MjModel.from_xml_path(str(alone)).nu == len(WHEELS)
    (registered,) = register_specs(spec)
    robot = assembler.assemble("Sparrow7", base=registered.__name__)
    model = robot.get_model()
    arm_root = model.body(robot.root_body).id
    base_root = model.body("mobilebase0_chassis").id
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    # The arm stands on the chassis's top face: 0.05 m above the chassis's origin.
    assert data.xpos[arm_root][2] - data.xpos[base_root][2] == pytest.approx(0.05, abs=1e-9)
    assert {model.actuator(a).name for a in range(model.nu)} >= {f"mobilebase0_{w}" for w in wheels}


def test_a_cart_carrying_an_arm_is_a_robot_whose_wheels_are_base_joints_and_not_arm_joints(
    write: Callable[[str, str], Path],
) -> None:
    fields, spec = _written(write, arm=True)
    assert "kind" not in fields and fields["morphology"] == "manipulator"
    wheels = [f"{side}_wheel_joint" for side, _, _ in WHEELS]
    assert fields["joint_groups"] == {"right": ["joint1", "joint2", "joint3"], "base": wheels}
    assert fields["eef_bodies"] == {"right": "fore"}
    (registered,) = register_specs(spec)
    assert assembler.create_robot(registered.__name__).get_model().njnt == 7
