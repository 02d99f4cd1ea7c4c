"""Record what robosuite's controllers output from given states, to compare across MuJoCo versions:
``python -m tests.robosuite.record_torques FOLDER`` writes ``torques_mujoco-<version>_numba-<mode>.npz``.
The two files beside this module were made so on MuJoCo 3.9.0 (the version robosuite 1.5.2 runs
unpatched), once as is and once with ``NUMBA_DISABLE_JIT=1`` (robosuite's transforms compiled by
numba round differently, by up to 5e-6 in these torques, from the same functions run by Python).

For Lift with robosuite's Panda and with our Sparrow7 (each with its default controller, OSC_POSE
for the arm), a seeded random rollout gives ``SAMPLES`` states. At each state the record keeps the
state (qpos, qvel, qacc_warmstart, ctrl, time), the action, the arm's torques robosuite's controller
writes for that action from that state, and the state one plain ``mj_step`` later with those torques.
The torques depend on MuJoCo through the mass matrix and the Jacobians, so a later MuJoCo given the
same model and states must give the same torques (:mod:`tests.robosuite.test_versions`); the
inertial fields of the compiled model are recorded as well, since MuJoCo's compiler changed them
slightly. The next states differ by what MuJoCo's physics changed.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

CASES = (("Lift", "Panda"), ("Lift", "Sparrow7"))
SAMPLES = 12
STATE_FIELDS = ("qpos", "qvel", "qacc_warmstart", "ctrl")
INERTIAL_FIELDS = ("body_mass", "body_inertia", "body_ipos", "body_iquat")
"""The compiled model's fields the mass matrix is made of (recorded too: MuJoCo's compiler changed)."""


def record_name(version: str) -> str:
    """The record's file name for MuJoCo ``version`` and this process's numba mode."""
    import numba
    import robosuite.macros

    compiled = robosuite.macros.ENABLE_NUMBA and not numba.config.DISABLE_JIT
    return f"torques_mujoco-{version}_numba-{'jit' if compiled else 'off'}.npz"


def make(env_name: str, robot: str) -> Any:
    """The environment, as the tests make it (no renderer, no cameras), reset with seed 0."""
    import robosuite

    import assembler.robosuite  # noqa: F401  (Sparrow7 enters robosuite; robosuite's Panda stays its own)

    env = robosuite.make(
        env_name,
        robots=robot,
        has_renderer=False,
        has_offscreen_renderer=False,
        use_camera_obs=False,
        ignore_done=True,
        seed=0,
    )
    env.reset()
    return env


def set_state(env: Any, sample: dict[str, np.ndarray]) -> None:
    """Put the recorded state into the environment's data and recompute what follows from it."""
    data = env.sim.data._data
    for field in STATE_FIELDS:
        getattr(data, field)[:] = sample[field]
    data.time = float(sample["time"])
    mujoco.mj_forward(env.sim.model._model, data)


def arm_torques(env: Any, action: np.ndarray) -> np.ndarray:
    """What the robot's controller writes into the arm's actuators for ``action`` from the current state."""
    robot = env.robots[0]
    for controller in robot.composite_controller.part_controllers.values():
        controller.update(force=True)  # the mass matrix, Jacobians and pose of the state just set
    robot.composite_controller.reset()  # goals at this state: the torques depend on state and action only
    robot.control(action, policy_step=True)
    return np.array(env.sim.data.ctrl[robot._ref_actuators_indexes_dict["right"]])


def plain_step(model: mujoco.MjModel, sample: dict[str, np.ndarray], ctrl: np.ndarray) -> mujoco.MjData:
    """One ``mj_step`` of plain MuJoCo from the recorded state with ``ctrl``, in fresh data."""
    data = mujoco.MjData(model)
    for field in STATE_FIELDS:
        getattr(data, field)[:] = sample[field]
    data.time = float(sample["time"])
    data.ctrl[:] = ctrl
    mujoco.mj_step(model, data)
    return data


def record(folder: str) -> None:
    recorded: dict[str, np.ndarray] = {"mujoco": np.array(mujoco.__version__)}
    for env_name, robot in CASES:
        env = make(env_name, robot)
        for field in INERTIAL_FIELDS:
            recorded[f"{robot}/model/{field}"] = np.array(getattr(env.sim.model._model, field))
        rng = np.random.default_rng(1)
        low, high = (np.clip(bound, -1, 1) for bound in env.action_spec)
        for index in range(SAMPLES):
            env.step(rng.uniform(low, high))
            data = env.sim.data._data
            sample = {field: np.array(getattr(data, field)) for field in STATE_FIELDS}
            sample["time"] = np.array(data.time)
            action = rng.uniform(low, high)
            sample["action"] = action
            sample["torques"] = arm_torques(env, action)
            sample["step_ctrl"] = np.array(data.ctrl)
            after = plain_step(env.sim.model._model, sample, sample["step_ctrl"])
            sample["next_qpos"], sample["next_qvel"] = np.array(after.qpos), np.array(after.qvel)
            set_state(env, sample)  # the rollout goes on from the recorded state
            recorded.update({f"{robot}/{index}/{key}": value for key, value in sample.items()})
        env.close()
    np.savez(Path(folder) / record_name(mujoco.__version__), **recorded)


if __name__ == "__main__":
    record(sys.argv[1])
