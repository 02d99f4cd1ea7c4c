"""Actuators get the gains MuJoCo 3.16+ gives them from default classes, on every supported MuJoCo.

The defaults below are those of robosuite's Inspire and Fourier hands (a main default written with
``<muscle>``, ``<motor>`` and ``<position>``) and of its Spot (a class with ``<position>`` then
``<motor>``). Before MuJoCo 3.16 the position servos kept the muscle's numbers (a constant force
and a damping term) and the motors the position's bias; these tests fail there without
:mod:`assembler.mjcf.actuator_defaults`.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.mjcf.actuator_defaults import rule_is_native

DEFAULTS = """\
  <default>
    <muscle ctrllimited="true" ctrlrange="0 100"/>
    <motor ctrllimited="true" ctrlrange="-3 3"/>
    <position ctrllimited="true" kp="10"/>
    <default class="spot">
      <position kp="500" kv="40"/>
      <motor ctrlrange="-70 70" ctrllimited="true"/>
    </default>
  </default>
"""

BODY_AND_ACTUATORS = """\
  <worldbody>
    <body name="palm">
      <geom size="0.05" mass="0.1"/>
      <body name="finger" pos="0.1 0 0">
        <joint name="proximal" axis="0 1 0" range="0 1.6"/>
        <geom type="capsule" fromto="0 0 0 0.05 0 0" size="0.01" mass="0.02"/>
        <body name="tip" pos="0.05 0 0">
          <joint name="distal" axis="0 1 0" range="0 1.8"/>
          <geom type="capsule" fromto="0 0 0 0.04 0 0" size="0.01" mass="0.01"/>
          <body name="nail" pos="0.04 0 0">
            <joint name="nail" axis="0 0 1" range="-0.5 0.5"/>
            <geom size="0.01" mass="0.005"/>
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    {actuators}
  </actuator>
"""

WITH_DEFAULTS = """\
    <position name="distal_drive" joint="distal" ctrlrange="0 1.8" kp="2"/>
    <position name="proximal_drive" joint="proximal" ctrlrange="0 1.6"/>
    <motor name="nail_motor" class="spot" joint="nail"/>"""

WRITTEN_OUT = """\
    <position name="distal_drive" joint="distal" ctrlrange="0 1.8" kp="2"/>
    <position name="proximal_drive" joint="proximal" ctrlrange="0 1.6" kp="10"/>
    <motor name="nail_motor" joint="nail" ctrlrange="-70 70"/>"""
"""The same actuators with what the new rule lets them inherit written on them, and no defaults."""

FIELDS = ("gaintype", "biastype", "dyntype", "gainprm", "biasprm", "dynprm", "ctrlrange")


def _robot(write: Callable[[str, str], Path], name: str, mjcf: str) -> mujoco.MjModel:
    write(f"robots/{name.lower()}.xml", mjcf)
    (cls,) = assembler.register_specs(
        write(f"robots/{name.lower()}.yaml", f"name: {name}\nmjcf: {name.lower()}.xml\n")
    )
    return cls(idn=0).get_model()


def _hand(write: Callable[[str, str], Path], name: str = "ClassHand") -> mujoco.MjModel:
    body = BODY_AND_ACTUATORS.format(actuators=WITH_DEFAULTS)
    return _robot(write, name, f'<mujoco model="hand">\n{DEFAULTS}{body}</mujoco>\n')


def test_position_servos_hold_still_when_their_class_also_defines_muscle_and_motor_defaults(write) -> None:  # type: ignore[no-untyped-def]
    model = _hand(write)
    data = mujoco.MjData(model)
    data.qpos[:] = [0.4, 0.9, 0.1]
    data.qvel[:] = [0.5, -0.3, 0.2]
    data.ctrl[:2] = [0.9, 0.4]  # each servo's setpoint is its joint's position: no error to correct
    mujoco.mj_forward(model, data)
    assert data.actuator_force[:2] == pytest.approx([0.0, 0.0], abs=1e-12)


def test_actuators_inherit_only_what_the_same_shortcut_declares(write) -> None:  # type: ignore[no-untyped-def]
    ours = _hand(write)
    body = BODY_AND_ACTUATORS.format(actuators=WRITTEN_OUT)
    reference = _robot(write, "PlainHand", f'<mujoco model="hand">\n{body}</mujoco>\n')
    for name in ("distal_drive", "proximal_drive", "nail_motor"):
        for field in FIELDS:
            got = getattr(ours.actuator(f"robot0_{name}"), field)
            expected = getattr(reference.actuator(f"robot0_{name}"), field)
            assert np.array_equal(got, expected), f"{name}.{field}: {got} != {expected}"


def test_defaults_in_an_included_file_follow_the_same_rule(write) -> None:  # type: ignore[no-untyped-def]
    write("robots/hand_defaults.xml", f"<mujoco>\n{DEFAULTS}</mujoco>\n")
    body = BODY_AND_ACTUATORS.format(actuators=WITH_DEFAULTS)
    ours = _robot(
        write,
        "IncludedHand",
        f'<mujoco model="hand">\n  <include file="hand_defaults.xml"/>\n{body}</mujoco>\n',
    )
    reference = _hand(write)
    for field in FIELDS:
        assert np.array_equal(getattr(ours, f"actuator_{field}"), getattr(reference, f"actuator_{field}")), (
            field
        )


@pytest.mark.parametrize(
    ("version", "native"),
    [("3.9.0", False), ("3.15.2", False), ("3.16.0", True), ("3.17.1", True), ("4.0.0", True)],
)
def test_the_rule_is_applied_by_us_only_before_mujoco_3_16(version: str, native: bool) -> None:
    assert rule_is_native(version) is native
