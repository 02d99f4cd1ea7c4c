"""robosuite's torque controllers see a motor-driven joint's limit: in a robosuite environment, the
torque limits robosuite's Robot reads (``actuator_ctrlrange``) and its controllers clip to are each
motor's ±(peak or stall torque)·N·η, computed here from the shipped datasheet values.

A joint ``control: torque`` drives already has that ctrlrange; a position servo becomes a motor of its
forcerange under ``robosuite.actuation: torque``; a DC motor driven in volts (``control: voltage``)
becomes, under ``robosuite.actuation: torque``, the motor ``control: torque`` gives its joint (else
robosuite's torques would be written into its ctrl as volts, clipped at ±voltage). The environment
runs in its own process (robosuite's registries are module globals), stepped with OSC actions at the
ends of its action space, and with a joint torque controller asking far more than any motor gives.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from assembler.models.motor_table import MOTORS  # noqa: E402
from tests.robosuite.processes import result  # noqa: E402

GEAR_RATIO, EFFICIENCY = 53.0, 0.7
"""The maxon EC-max 22's planetary gearhead on joint7 (the docs/motors.md example)."""

SPEC = f"""\
name: MotorSparrow
extends: Sparrow7
motors:
  - {{match: 'joint[1-4]', motor: KinovaGen3LargeActuator, control: torque}}
  - {{match: 'joint[56]', motor: KinovaGen3SmallActuator, control: position, kp: 300, dampratio: 1}}
  - {{match: joint7, motor: MaxonECmax22, gear_ratio: {GEAR_RATIO}, efficiency: {EFFICIENCY}, control: voltage}}
"""
"""Sparrow7 (robosuite.actuation: torque) with Kinova Gen3 actuators on joints 1-6, torque- and
position-controlled, and a maxon motor taking volts on joint 7."""

SCRIPT = """
import json, numpy as np, robosuite, assembler, assembler.robosuite
assembler.robosuite.register("my_robots/")

def make(**options):
    return robosuite.make("Lift", robots="MotorSparrow", has_renderer=False, has_offscreen_renderer=False,
                          use_camera_obs=False, horizon=100, **options)

def run(env, steps):
    env.reset()
    arm = env.robots[0]._ref_arm_joint_actuator_indexes
    low, high = env.action_spec
    actions, ctrl = [], []
    for step in range(steps):
        actions.append(np.where(np.arange(len(low)) % 2 == step // 10 % 2, high, low))
        env.step(actions[-1])
        ctrl.append(env.sim.data.ctrl[arm].tolist())
    return np.array(actions)[:, :len(arm)].tolist(), ctrl

env = make()  # the robot's default controller: robosuite's OSC_POSE
robot, model = env.robots[0], env.sim.model
arm = robot._ref_arm_joint_actuator_indexes
_, osc = run(env, 40)
config = robosuite.load_composite_controller_config(controller="BASIC")
config["body_parts"]["right"].update(type="JOINT_TORQUE", output_max=1000, output_min=-1000,
                                     use_torque_compensation=False)
actions, joint_torque = run(make(controller_configs=config), 20)
joint7 = model.actuator("robot0_joint7").id
torque = assembler.assemble("MotorSparrow", overrides=["motors[2].control=torque"]).get_model(cache=False)
theirs = torque.actuator("robot0_joint7").id
fields = ("actuator_gaintype", "actuator_gainprm", "actuator_biastype", "actuator_biasprm", "actuator_dyntype",
          "actuator_gear", "actuator_ctrlrange", "actuator_forcerange", "actuator_forcelimited")
print("RESULT " + json.dumps({
    "names": [model.actuator(i).name for i in arm],
    "torque_limits": [v.tolist() for v in robot.torque_limits],
    "controller_limits": [np.asarray(v).tolist() for v in robot.part_controllers["right"].actuator_limits],
    "osc_ctrl": osc,
    "actions": actions,
    "joint_torque_ctrl": joint_torque,
    "as_torque_control": {f: np.array_equal(getattr(model, f)[joint7], getattr(torque, f)[theirs]) for f in fields},
}))
"""


def _limits() -> list[float]:
    """Each joint's torque limit from the motor specs' datasheet values, (peak or stall torque)·N·η at
    the motor shaft: the Kinova actuators' torque is the joint's (their gear ratio and efficiency 1),
    the maxon motor gives no peak torque, so its limit is its stall torque through the gearhead."""
    names = ("KinovaGen3LargeActuator", "KinovaGen3SmallActuator", "MaxonECmax22")
    large, small, maxon = (MOTORS.lookup(name).spec for name in names)
    assert {m.ratings_at for m in (large, small, maxon)} == {"motor"}
    limit: list[float] = []
    for motor, joints, ratio, efficiency in (
        (large, 4, large.gear_ratio, large.efficiency),
        (small, 2, small.gear_ratio, small.efficiency),
        (maxon, 1, GEAR_RATIO, EFFICIENCY),
    ):
        torque = motor.peak_torque if motor.peak_torque is not None else motor.stall_torque
        assert torque is not None
        limit += [torque * ratio * efficiency] * joints
    return limit


@pytest.fixture(scope="module")
def seen(tmp_path_factory: pytest.TempPathFactory) -> Any:
    root = tmp_path_factory.mktemp("motors")
    (root / "my_robots").mkdir()
    (root / "my_robots" / "motorsparrow.yaml").write_text(SPEC)
    return result(SCRIPT, Path(root))


def test_robosuites_torque_limits_are_each_motors_limit_at_its_joint(seen: Any) -> None:
    assert seen["names"] == [f"robot0_joint{i}" for i in range(1, 8)]
    limits = np.array(_limits())
    np.testing.assert_allclose(seen["torque_limits"], [-limits, limits], rtol=1e-12)
    np.testing.assert_allclose(seen["controller_limits"], [-limits, limits], rtol=1e-12)


def test_robosuites_controllers_clip_their_torques_to_the_motor_limits(seen: Any) -> None:
    limits = np.array(_limits())
    # OSC_POSE driven to the ends of its action space: every torque within its motor's limit
    assert (np.abs(np.array(seen["osc_ctrl"])) <= limits * (1 + 1e-12)).all()
    # JOINT_TORQUE asking ±1000 N·m of every joint: each gets exactly its motor's limit, with the sign asked
    expected = np.sign(np.array(seen["actions"])) * limits
    np.testing.assert_allclose(seen["joint_torque_ctrl"], expected, rtol=1e-12)


def test_a_voltage_driven_joint_is_in_robosuite_the_motor_torque_control_gives_it(seen: Any) -> None:
    assert seen["as_torque_control"] == dict.fromkeys(seen["as_torque_control"], True)
