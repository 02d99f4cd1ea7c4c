"""A one-joint arm and a motor spec written to files, for tests of motor-driven joints."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import assembler

Write = Callable[[str, str], Path]

SPINNER_MJCF = """\
<mujoco model="spinner">
  <compiler angle="radian" autolimits="true"/>
  <option timestep="0.0005" gravity="0 0 0"/>
  <worldbody>
    <body name="base">
      <body name="rotor">
        <joint name="spin" axis="0 0 1"{extra}/>
        <geom type="cylinder" size="0.05 0.01" mass="0.1"/>
        <body name="right_hand"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
"""One free-spinning hinge (no range, no gravity torque) with a 0.1 kg disc: no load but inertia."""

MOTOR = {
    "voltage": 24.0,
    "torque_constant": 0.05,
    "resistance": 1.2,
    "rotor_inertia": 1.0e-5,
    "gear_ratio": 10.0,
    "efficiency": 0.9,
}
"""A made-up brushed motor with a 10:1 gearbox (numbers chosen, not a datasheet's)."""


def motor_yaml(name: str = "TestMotor", **fields: object) -> str:
    values = {**MOTOR, **fields}
    lines = [f"kind: motor\nname: {name}\nsource: a test's own numbers"]
    lines += [f"{key}: {value}" for key, value in values.items() if value is not None]
    return "\n".join(lines) + "\n"


def motor_robot(
    write: Write, entry: str, motor: str | None = None, joint_extra: str = ""
) -> assembler.RobotModel:
    """The spinner with ``motors: [entry]`` (text after the entry continues the spec), registered with
    its motor spec (``motor``: the spec's text); ``joint_extra``: attributes of the joint in the MJCF."""
    write("rig/spinner.xml", SPINNER_MJCF.format(extra=joint_extra))
    motor_file = write("rig/motor.yaml", motor if motor is not None else motor_yaml())
    robot_file = write("rig/robot.yaml", f"name: Spinner\nmjcf: spinner.xml\nmotors:\n  - {entry}\n")
    classes = assembler.register_specs(motor_file, robot_file)
    (cls,) = [c for c in classes if c.__name__ == "Spinner"]
    return cls(idn=0)  # type: ignore[return-value]
