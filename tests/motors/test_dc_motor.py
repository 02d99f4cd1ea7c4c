"""A voltage-controlled joint behaves as the datasheet's DC motor, in MuJoCo's own model and in the
``general`` equivalent: no-load speed ``V/(kt·N)`` and stall torque ``N·η·kt·V/R`` within 1%."""

from __future__ import annotations

import mujoco
import pytest

from tests.motors.rigs import MOTOR, Write, motor_robot

KINDS = ("dcmotor", "general")


def _settled_speed(model: mujoco.MjModel, voltage: float) -> float:
    data = mujoco.MjData(model)
    data.ctrl[0] = voltage
    for _ in range(int(1.0 / model.opt.timestep)):  # 1 s: over 100 mechanical time constants
        mujoco.mj_step(model, data)
    return float(data.qvel[0])


@pytest.mark.parametrize("kind", KINDS)
def test_a_voltage_driven_joint_without_load_reaches_the_no_load_speed(write: Write, kind: str) -> None:
    robot = motor_robot(
        write, f"{{match: spin, motor: TestMotor, control: voltage, voltage_actuator: {kind}}}"
    )
    model = robot.get_model()
    assert model.actuator_gaintype[0] == (mujoco.mjtGain.mjGAIN_DCMOTOR if kind == "dcmotor" else 0)
    no_load = MOTOR["voltage"] / (MOTOR["torque_constant"] * MOTOR["gear_ratio"])
    assert _settled_speed(model, MOTOR["voltage"]) == pytest.approx(no_load, rel=0.01)
    assert _settled_speed(model, -MOTOR["voltage"] / 2) == pytest.approx(-no_load / 2, rel=0.01)


@pytest.mark.parametrize("kind", KINDS)
def test_a_voltage_driven_joint_held_still_delivers_the_stall_torque(write: Write, kind: str) -> None:
    entry = f"{{match: spin, motor: TestMotor, control: voltage, voltage_actuator: {kind}}}"
    robot = motor_robot(write, entry, joint_extra=' range="-0.001 0.001"')  # the joint limit holds it
    model = robot.get_model()
    data = mujoco.MjData(model)
    data.ctrl[0] = MOTOR["voltage"]
    for _ in range(2000):
        mujoco.mj_step(model, data)
    n, eta, kt = MOTOR["gear_ratio"], MOTOR["efficiency"], MOTOR["torque_constant"]
    stall = n * eta * kt * MOTOR["voltage"] / MOTOR["resistance"]
    assert abs(data.qvel[0]) < 1e-3
    assert data.qfrc_actuator[0] == pytest.approx(stall, rel=0.01)


def test_the_two_voltage_actuators_give_the_same_torque_at_every_speed(write: Write) -> None:
    models = {}
    for kind in KINDS:
        entry = f"{{match: spin, motor: TestMotor, control: voltage, voltage_actuator: {kind}}}"
        models[kind] = motor_robot(write, entry).get_model()
    for speed in (-30.0, 0.0, 12.5, 48.0):
        torques = []
        for model in models.values():
            data = mujoco.MjData(model)
            data.qvel[0], data.ctrl[0] = speed, 17.0
            mujoco.mj_forward(model, data)
            torques.append(float(data.qfrc_actuator[0]))
        assert torques[0] == pytest.approx(torques[1], rel=1e-12, abs=1e-12)
