"""Joints a base spec adds (``added_joints``): planar mobile joints with velocity actuators, as
robosuite's SpotFloating adds them, and a clear error for a body that does not exist."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import assembler
from assembler.errors import MjcfError
from assembler.models.provenance import Provenance

BODY_MJCF = """\
<mujoco model="hull">
  <worldbody>
    <body name="hull">
      <freejoint/>
      <geom type="box" size="0.3 0.2 0.1" mass="20"/>
      <body name="support" pos="0 0 0.1"/>
    </body>
  </worldbody>
</mujoco>
"""

SPEC = """\
kind: base
name: Hull
type: legged
mjcf: hull.xml
remove_free_joint: true
added_joints:
  - name: forward
    type: slide
    axis: [1, 0, 0]
    body: {body}
    frictionloss: 250
    actuator: {{name: drive_forward, kv: 1000, ctrlrange: [-1, 1], forcerange: [-600, 600]}}
  - name: yaw
    type: hinge
    axis: [0, 0, 1]
"""


def _base(write: Callable[[str, str], Path], body: str = "hull") -> assembler.RobotBaseModel:
    write("hull.xml", BODY_MJCF)
    (cls,) = assembler.register_specs(write("hull.yaml", SPEC.format(body=body)))
    base = cls(idn=0)
    assert isinstance(base, assembler.RobotBaseModel)
    return base


def test_added_joints_replace_the_free_joint_and_are_driven(write: Callable[[str, str], Path]) -> None:
    model = _base(write).compile_alone()
    assert [model.joint(i).name for i in range(model.njnt)] == ["leg0_forward", "leg0_yaw"]
    assert model.jnt_type.tolist() == [mujoco.mjtJoint.mjJNT_SLIDE, mujoco.mjtJoint.mjJNT_HINGE]
    assert model.joint("leg0_forward").axis.tolist() == [1.0, 0.0, 0.0]
    assert model.dof_frictionloss.tolist() == [250.0, 0.0]
    drive = model.actuator("leg0_drive_forward")
    assert (drive.gainprm[0], drive.biasprm[2]) == (1000.0, -1000.0)  # a velocity servo
    assert drive.ctrlrange.tolist() == [-1.0, 1.0] and drive.forcerange.tolist() == [-600.0, 600.0]


def test_added_joints_show_their_source_in_inspect(write: Callable[[str, str], Path]) -> None:
    assert _base(write).joint_values["forward"]["frictionloss"].source == Provenance("added", index=0)


def test_an_added_joint_on_a_missing_body_names_the_bodies(write: Callable[[str, str], Path]) -> None:
    with pytest.raises(
        MjcfError,
        match=r"hull.yaml:7:3: added_joints: added joint 'forward': no body 'chassis'. Bodies: hull, support",
    ):
        _base(write, body="chassis").check()
