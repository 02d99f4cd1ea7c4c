"""What a motor gives its joint, computed here from the motor spec's own numbers: armature, friction,
damping, force limits, and the precedence of the spec's joints: entries, the motor, the file, 0."""

from __future__ import annotations

import mujoco
import pytest

from assembler.cli import main
from tests.motors.rigs import MOTOR, Write, motor_robot, motor_yaml

FRICTION, VISCOUS, PEAK = 0.002, 3.0e-5, 0.4


def _joint(robot: object, attribute: str) -> float:
    model = robot.get_model()  # type: ignore[attr-defined]
    return float(getattr(model.joint(robot.naming_prefix + "spin"), attribute)[0])  # type: ignore[attr-defined]


def test_joint_values_are_the_motor_values_through_the_gearbox(write: Write) -> None:
    motor = motor_yaml(friction_torque=FRICTION, viscous_friction=VISCOUS, gearbox_inertia=2.0e-4)
    robot = motor_robot(write, "{match: spin, motor: TestMotor}", motor)
    n = MOTOR["gear_ratio"]
    assert _joint(robot, "armature") == pytest.approx(MOTOR["rotor_inertia"] * n**2 + 2.0e-4, rel=1e-12)
    assert _joint(robot, "frictionloss") == pytest.approx(FRICTION * n, rel=1e-12)
    assert _joint(robot, "damping") == pytest.approx(VISCOUS * n**2, rel=1e-12)


def test_an_entry_gearbox_replaces_the_motor_spec_gearbox_and_its_inertia(write: Write) -> None:
    motor = motor_yaml(gearbox_inertia=2.0e-4)
    robot = motor_robot(write, "{match: spin, motor: TestMotor, gear_ratio: 36, efficiency: 0.8}", motor)
    assert _joint(robot, "armature") == pytest.approx(MOTOR["rotor_inertia"] * 36**2, rel=1e-12)
    model = robot.get_model()
    stall = 36 * 0.8 * MOTOR["torque_constant"] * MOTOR["voltage"] / MOTOR["resistance"]
    assert model.actuator_forcerange[0].tolist() == pytest.approx([-stall, stall], rel=1e-12)


def test_a_torque_motor_is_limited_to_the_peak_torque_through_the_gearbox(write: Write) -> None:
    robot = motor_robot(
        write, "{match: spin, motor: TestMotor, control: torque}", motor_yaml(peak_torque=PEAK)
    )
    model = robot.get_model()
    limit = PEAK * MOTOR["gear_ratio"] * MOTOR["efficiency"]
    assert model.actuator_forcerange[0].tolist() == pytest.approx([-limit, limit], rel=1e-12)
    assert model.actuator_ctrlrange[0].tolist() == pytest.approx([-limit, limit], rel=1e-12)
    assert model.actuator_gainprm[0][0] == 1.0


def test_a_position_servo_takes_its_gains_and_the_motor_force_limit(write: Write) -> None:
    entry = "{match: spin, motor: TestMotor, control: position, kp: 50, dampratio: 1}"
    robot = motor_robot(write, entry, joint_extra=' range="-2 2"')
    model = robot.get_model()
    stall = MOTOR["gear_ratio"] * MOTOR["efficiency"] * MOTOR["torque_constant"] * MOTOR["voltage"]
    stall /= MOTOR["resistance"]
    assert model.actuator_gainprm[0][0] == 50.0
    assert model.actuator_biastype[0] == mujoco.mjtBias.mjBIAS_AFFINE
    assert model.actuator_forcerange[0].tolist() == pytest.approx([-stall, stall], rel=1e-12)
    assert model.actuator_ctrlrange[0].tolist() == [-2.0, 2.0]


def test_ratings_at_the_output_of_an_integrated_actuator_are_the_joint_ratings(write: Write) -> None:
    # A servo's datasheet: stall torque and no-load speed after its own 353.5:1 gearbox, no constants.
    servo = "kind: motor\nname: TestMotor\nsource: test\nvoltage: 12\ngear_ratio: 353.5\nratings_at: output\n"
    servo += "stall_torque: 4.1\nno_load_speed: 4.817\n"
    robot = motor_robot(write, "{match: spin, motor: TestMotor, control: voltage}", servo)
    model = robot.get_model()
    data = mujoco.MjData(model)
    data.ctrl[0] = 12.0
    mujoco.mj_forward(model, data)
    assert data.qfrc_actuator[0] == pytest.approx(4.1, rel=1e-9)
    data.qvel[0] = 4.817
    mujoco.mj_forward(model, data)
    assert data.qfrc_actuator[0] == pytest.approx(0.0, abs=1e-9)


def test_the_spec_joints_entry_wins_over_the_motor_and_rules_skip_motor_driven_joints(write: Write) -> None:
    robot_text = "{match: spin, motor: TestMotor}\njoints:\n  - {match: spin, armature: 0.5}"
    robot = motor_robot(write, robot_text)
    assert _joint(robot, "armature") == 0.5  # joints: entry
    assert (
        _joint(robot, "damping") == 0.0
    )  # robosuite's rule (0.1) does not apply: no motor value, no file value
    assert _joint(robot, "frictionloss") == 0.0
    assert str(robot.joint_values["spin"]["armature"].source) == "spec joints[0]"


def test_the_file_value_stays_where_the_motor_gives_none(write: Write) -> None:
    robot = motor_robot(write, "{match: spin, motor: TestMotor}", joint_extra=' damping="0.7"')
    assert _joint(robot, "damping") == 0.7
    assert _joint(robot, "armature") == pytest.approx(MOTOR["rotor_inertia"] * MOTOR["gear_ratio"] ** 2)


def test_a_motor_actuator_replaces_the_joint_own_and_says_so(write: Write) -> None:
    robot = motor_robot(write, "{match: spin, motor: TestMotor}\nactuators:\n  - {match: spin, kp: 10}")
    (record,) = robot.actuator_table
    assert (record.source, record.type, record.note) == (
        "spec motors[0]",
        "motor",
        "replaces 'spin' (spec actuators[0])",
    )
    assert robot.get_model().nu == 1


def test_inspect_prints_each_derived_value_with_its_motor_formula_and_numbers(
    write: Write, capsys: pytest.CaptureFixture[str]
) -> None:
    robot = motor_robot(write, "{match: spin, motor: TestMotor, control: voltage}")
    folder = str(type(robot).loaded.document.path.parent)  # type: ignore[union-attr]
    assert main(["--specs", folder, "inspect", "Spinner"]) == 0
    out = capsys.readouterr().out
    armature = MOTOR["rotor_inertia"] * MOTOR["gear_ratio"] ** 2
    assert f"robot0_spin  armature {armature:.6g} = 1e-05 kg·m² × 10²  (motor TestMotor, motors[0]" in out
    assert "no-load speed 48 = 24 / (0.05 × 10)" in out
    assert "stall torque 9 = 10 × 0.9 × 0.05 × 24 / 1.2" in out
