"""A voltage-controlled joint behaves as the datasheet's DC motor, in MuJoCo's own model and in the
``general`` equivalent: no-load speed ``V/(kt·N)`` and stall torque ``N·η·kt·V/R`` within 1%, for the
rig's made-up motor and for the shipped maxon RE 25 with its GP 26 B 84:1 gearhead."""

from __future__ import annotations

import mujoco
import pytest

from tests.motors.rigs import MOTOR, Write, motor_robot

KINDS = ("dcmotor", "general")

RE25_GP26B = {
    "voltage": 24.0,
    "torque_constant": 0.0234,
    "resistance": 2.32,
    "gear_ratio": 84.0,
    "efficiency": 0.59,
}
"""maxon's catalogue pages, as specs/motors/maxon_re25_gp26b.yaml cites them: the RE 25 (118752) at 24 V,
23.4 mN·m/A, 2.32 Ω, behind the GP 26 B (144039), 84:1, 59% max efficiency."""

SHEETS = {"TestMotor": MOTOR, "MaxonRE25GP26B": RE25_GP26B}
"""Each motor's datasheet numbers: the rig's own motor spec, and a shipped one (the rig's spec unused)."""


def _settled_speed(model: mujoco.MjModel, voltage: float) -> float:
    data = mujoco.MjData(model)
    data.ctrl[0] = voltage
    for _ in range(int(1.0 / model.opt.timestep)):  # 1 s: over 100 mechanical time constants
        mujoco.mj_step(model, data)
    return float(data.qvel[0])


@pytest.mark.parametrize("motor", sorted(SHEETS))
@pytest.mark.parametrize("kind", KINDS)
def test_a_voltage_driven_joint_without_load_reaches_the_no_load_speed(
    write: Write, kind: str, motor: str
) -> None:
    robot = motor_robot(write, f"{{match: spin, motor: {motor}, control: voltage, voltage_actuator: {kind}}}")
    model = robot.get_model()
    assert model.actuator_gaintype[0] == (mujoco.mjtGain.mjGAIN_DCMOTOR if kind == "dcmotor" else 0)
    sheet = SHEETS[motor]
    no_load = sheet["voltage"] / (sheet["torque_constant"] * sheet["gear_ratio"])
    assert _settled_speed(model, sheet["voltage"]) == pytest.approx(no_load, rel=0.01)
    assert _settled_speed(model, -sheet["voltage"] / 2) == pytest.approx(-no_load / 2, rel=0.01)


@pytest.mark.parametrize("motor", sorted(SHEETS))
@pytest.mark.parametrize("kind", KINDS)
def test_a_voltage_driven_joint_held_still_delivers_the_stall_torque(
    write: Write, kind: str, motor: str
) -> None:
    entry = f"{{match: spin, motor: {motor}, control: voltage, voltage_actuator: {kind}}}"
    robot = motor_robot(write, entry, joint_extra=' range="-0.001 0.001"')  # the joint limit holds it
    model = robot.get_model()
    data = mujoco.MjData(model)
    sheet = SHEETS[motor]
    data.ctrl[0] = sheet["voltage"]
    for _ in range(2000):
        mujoco.mj_step(model, data)
    n, eta, kt = sheet["gear_ratio"], sheet["efficiency"], sheet["torque_constant"]
    stall = n * eta * kt * sheet["voltage"] / sheet["resistance"]
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
