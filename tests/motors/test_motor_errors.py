"""A mistake in a motor spec or a motors: entry is one line at the file, line and column to change."""

from __future__ import annotations

import re

import pytest

import assembler
from assembler.errors import AssemblerError
from tests.motors.rigs import Write, motor_robot, motor_yaml

BAD_MOTORS = [
    (
        {"rotor_inertia": -1.0e-5},
        r"^\S+motor\.yaml:7:16: rotor_inertia: Input should be greater than or equal to 0$",
    ),
    ({"resistance": 0}, r"^\S+motor\.yaml:6:13: resistance: Input should be greater than 0$"),
    ({"voltage": "true"}, r"^\S+motor\.yaml:4:10: voltage: expected a number, got true$"),
    (
        {"stall_torque": 5.0},
        r"^\S+motor\.yaml:10:15: stall_torque: 5 N·m contradicts torque_constant × voltage / resistance = "
        r"0\.05 × 24 / 1\.2 = 1 N·m \(400% apart, tolerance 10%\); correct the value or the constants, "
        r"or give the datasheet's tolerance$",
    ),
    (
        {"no_load_speed": 400.0},
        r"^\S+motor\.yaml:10:16: no_load_speed: 400 rad/s contradicts voltage / torque_constant = 24 / 0\.05 "
        r"= 480 rad/s \(17% apart, tolerance 10%\)",
    ),
]


@pytest.mark.parametrize(("fields", "message"), BAD_MOTORS)
def test_a_bad_motor_spec_is_one_line_at_its_value(
    write: Write, fields: dict[str, float], message: str
) -> None:
    path = write("m/motor.yaml", motor_yaml(**fields))
    with pytest.raises(AssemblerError) as error:
        assembler.register_specs(path)
    assert re.match(message, str(error.value)), str(error.value)
    assert len(str(error.value).splitlines()) == 1


def test_a_motor_within_its_stated_tolerance_is_accepted(write: Write) -> None:
    path = write("m/motor.yaml", motor_yaml(tolerance=0.25, no_load_speed=400.0))
    assembler.register_specs(path)


def test_a_glob_matching_no_joint_names_the_joints_and_the_closest(write: Write) -> None:
    robot = motor_robot(write, "{match: 'spn*', motor: TestMotor}")
    with pytest.raises(
        AssemblerError,
        match=r"robot\.yaml:4:13: motors\[0\]\.match: no joint matches 'spn\*'\. "
        r"Did you mean 'spin'\? Joints: spin$",
    ):
        robot.get_model()


def test_an_unknown_motor_suggests_the_closest_name(write: Write) -> None:
    robot = motor_robot(write, "{match: spin, motor: TestMotr}")
    with pytest.raises(
        AssemblerError,
        match=r"robot\.yaml:4:26: motors\[0\]\.motor: unknown motor 'TestMotr'\. "
        r"Did you mean 'TestMotor'\?$",
    ):
        robot.get_model()


def test_voltage_control_without_the_motor_constants_says_what_is_missing(write: Write) -> None:
    motor = motor_yaml(torque_constant=None, resistance=None)
    robot = motor_robot(write, "{match: spin, motor: TestMotor, control: voltage}", motor)
    with pytest.raises(
        AssemblerError,
        match=r"motors\[0\]\.control: voltage control needs the motor's voltage, "
        r"torque_constant and resistance \(or voltage, stall_torque and no_load_speed\)",
    ):
        robot.get_model()


def test_gains_of_a_position_servo_on_a_torque_motor_are_refused(write: Write) -> None:
    robot_text = "{match: spin, motor: TestMotor, control: torque, kp: 5}"
    with pytest.raises(
        AssemblerError,
        match=r"robot\.yaml:4:5: motors\[0\]: kp is a position servo's gain; "
        r"control is torque$",
    ):
        motor_robot(write, robot_text)


def test_torque_control_without_any_torque_rating_says_what_to_add(write: Write) -> None:
    motor = motor_yaml(torque_constant=None, resistance=None)
    robot = motor_robot(write, "{match: spin, motor: TestMotor, control: torque}", motor)
    with pytest.raises(
        AssemblerError,
        match=r"robot\.yaml:4:46: motors\[0\]\.control: torque control needs a torque limit: motor 'TestMotor' "
        r"gives no peak_torque, stall_torque, nor voltage, torque_constant and resistance; add them, or use "
        r"control: null$",
    ):
        robot.get_model()
