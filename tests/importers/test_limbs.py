"""``assembler new`` on robots with feet: legs told from arms by the tree's shape, a quadruped written as
``morphology: legged`` (no arm, no gripper, a free joint), a humanoid's arms told right and left, and
the legged morphology built, listed and kept out of robosuite. Real files and real compiles."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest
import yaml

import assembler
from assembler.cli import main
from assembler.errors import AssemblerError
from assembler.models import LeggedModel
from assembler.registry.catalog import register_specs
from assembler.robosuite.conventions import offered

BOX = '<inertial pos="0 0 0" mass="0.5" diaginertia="0.001 0.001 0.001"/><geom type="capsule" size="0.02" fromto="0 0 0 0 0 -0.2"/>'


def _leg(name: str, x: float, y: float) -> str:
    return f"""
      <body name="{name}_hip" pos="{x} {y} 0">{BOX}
        <joint name="{name}_hip_joint" axis="1 0 0" range="-1 1"/>
        <body name="{name}_thigh" pos="0 0 -0.2">{BOX}
          <joint name="{name}_knee_joint" axis="0 1 0" range="-2 0"/>
          <body name="{name}_foot" pos="0 0 -0.2"><inertial pos="0 0 0" mass="0.1" diaginertia="1e-4 1e-4 1e-4"/>
            <geom type="sphere" size="0.02"/>
          </body>
        </body>
      </body>"""


def _arm(name: str, y: float) -> str:
    return f"""
      <body name="{name}_upper" pos="0 {y} 0.3">{BOX}
        <joint name="{name}_shoulder" axis="0 1 0" range="-3 3"/>
        <body name="{name}_lower" pos="0 0 -0.2">{BOX}
          <joint name="{name}_elbow" axis="0 1 0" range="-2 0"/>
          <body name="{name}_palm" pos="0 0 -0.2"><inertial pos="0 0 0" mass="0.1" diaginertia="1e-4 1e-4 1e-4"/></body>
        </body>
      </body>"""


def _robot(name: str, limbs: str) -> str:
    return f"""<mujoco model="{name}">
  <worldbody>
    <body name="trunk" pos="0 0 0.5">
      <freejoint/>
      <inertial pos="0 0 0" mass="5" diaginertia="0.05 0.05 0.05"/>
      <geom type="box" size="0.2 0.1 0.05"/>{limbs}
    </body>
  </worldbody>
</mujoco>
"""


QUADRUPED = _robot(
    "dog",
    "".join(
        _leg(n, x, y)
        for n, x, y in [("FL", 0.2, 0.1), ("FR", 0.2, -0.1), ("RL", -0.2, 0.1), ("RR", -0.2, -0.1)]
    ),
)
"""Four legs of two joints each under a floating trunk, no actuators."""

HUMANOID = _robot("walker", _leg("a", 0, 0.1) + _leg("b", 0, -0.1) + _arm("p", 0.25) + _arm("q", -0.25))
"""Two legs and two arms whose names say no side: the arms' sides are where they lie (+y: left)."""


def _written(write: Callable[[str, str], Path], name: str, text: str) -> tuple[dict[str, object], Path]:
    model = write(f"robots/{name}.xml", text)
    spec = model.with_name(f"{name}.yaml")
    assert main(["new", str(model), "-o", str(spec)]) == 0
    return yaml.safe_load(spec.read_text()), spec


def test_a_quadruped_is_written_legged_with_its_feet_and_no_arm_or_gripper(
    write: Callable[[str, str], Path],
) -> None:
    fields, spec = _written(write, "dog", QUADRUPED)
    assert fields["morphology"] == "legged"
    assert fields["feet"] == ["FL_foot", "FR_foot", "RL_foot", "RR_foot"]
    assert fields["joint_groups"] == {
        "legs": [f"{leg}_{joint}_joint" for leg in ("FL", "FR", "RL", "RR") for joint in ("hip", "knee")]
    }
    assert not {"eef_bodies", "default_grippers", "robosuite"} & set(fields)
    assert fields["mjlab"] == {"imu_body": "trunk", "soft_joint_pos_limit_factor": 0.9}  # what mjlab reads
    text = spec.read_text()
    assert "# decide: a legged robot stands on a floor" in text
    (cls,) = register_specs(spec)
    robot = assembler.create_robot(cls.__name__)
    assert isinstance(robot, LeggedModel) and robot.arms == ()
    assert robot.feet == [f"robot0_{leg}_foot" for leg in ("FL", "FR", "RL", "RR")]
    model = robot.get_model()
    assert model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE and model.nu == 8
    assert not offered(cls)  # robosuite's robots are manipulators


def test_a_humanoids_arms_are_told_right_and_left_by_where_they_lie(
    write: Callable[[str, str], Path],
) -> None:
    fields, spec = _written(write, "walker", HUMANOID)
    assert fields["morphology"] == "humanoid" and fields["arm_type"] == "bimanual"
    assert fields["eef_bodies"] == {"left": "p_palm", "right": "q_palm"}
    groups = fields["joint_groups"]
    assert isinstance(groups, dict)
    assert groups["left"] == ["p_shoulder", "p_elbow"] and groups["right"] == ["q_shoulder", "q_elbow"]
    assert len(groups["legs"]) == 4
    assert fields["default_grippers"] == {"left": None, "right": None}  # never a gripper guessed on a limb
    (cls,) = register_specs(spec)
    assert assembler.create_robot(cls.__name__).get_model().nu == 8


def test_an_arm_on_a_fixed_base_has_no_feet(write: Callable[[str, str], Path]) -> None:
    arm = _robot("arm", _arm("a", 0)).replace("<freejoint/>", "")
    fields, _ = _written(write, "arm", arm)
    assert fields["morphology"] == "manipulator"


@pytest.mark.parametrize(
    ("spec", "message"),
    [
        (
            "morphology: legged\nfeet: [FL_fot]\n",
            "feet[0]: no body named 'FL_fot' in the MJCF. Did you mean 'FL_foot'?",
        ),
        (
            "morphology: legged\neef_bodies: {right: trunk}\n",
            "eef_bodies names arm 'right', but a legged robot has no arms",
        ),
        ("feet: [FL_foot]\n", "feet: a manipulator has no legs; set morphology: legged for a legged robot"),
    ],
)
def test_a_legged_spec_names_what_is_wrong_in_one_line(
    write: Callable[[str, str], Path], spec: str, message: str
) -> None:
    write("robots/dog.xml", QUADRUPED)
    path = write("robots/dog.yaml", "name: Dog\nmjcf: dog.xml\n" + spec)
    with pytest.raises(AssemblerError, match=message.replace("[", r"\[").replace("(", r"\(")):
        (cls,) = register_specs(path)
        assembler.create_robot(cls.__name__).get_model()
