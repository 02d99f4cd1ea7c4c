"""The same environment on MuJoCo 3.9 and on the MuJoCo installed, the differences explained.

``torques_mujoco-3.9.0_numba-*.npz`` hold states of Lift with robosuite's Panda and with our Sparrow7, the
arm torques robosuite's controller gave from each on MuJoCo 3.9.0 (robosuite 1.5.2's version,
unpatched), the inertial fields of the compiled model and the state one plain ``mj_step`` later;
``record_torques.py`` made them. CI has one MuJoCo per environment, so what does not change is
recorded once and compared on whichever MuJoCo runs. The compiled models differ: MuJoCo 4.0's
compiler finds a principal inertia frame of Sparrow7's body 5 (a full inertia) 2e-7 away from 3.9's,
which alone moves Sparrow7's torques by 3e-8. Given the same model and states, the controllers (which
read the mass matrix through the patched ``mj_fullM`` call) give the same torques within 1e-9.
Trajectories differ between versions because
MuJoCo's physics changed, not robosuite's control: on each version robosuite's substep is one plain
``mj_step``, bit for bit, and on 3.9.0 that step reproduces the recorded next states exactly.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.record_torques import (  # noqa: E402
    CASES,
    INERTIAL_FIELDS,
    SAMPLES,
    STATE_FIELDS,
    arm_torques,
    make,
    plain_step,
    record_name,
    set_state,
)

RECORD = np.load(Path(__file__).with_name(record_name("3.9.0")))
ROBOTS = [robot for _, robot in CASES]


def _samples(robot: str) -> list[dict[str, np.ndarray]]:
    keys = {key.split("/")[-1] for key in RECORD.files if key.startswith(f"{robot}/0/")}
    return [{key: RECORD[f"{robot}/{index}/{key}"] for key in keys} for index in range(SAMPLES)]


@pytest.fixture(scope="module", params=CASES, ids=ROBOTS)
def env(request: pytest.FixtureRequest) -> Any:
    made = make(*request.param)
    yield made
    made.close()


def test_the_compiled_inertias_differ_from_mujoco_3_9s_by_at_most_a_principal_frame_rounding(
    env: Any,
) -> None:
    robot = type(env.robots[0].robot_model).__name__
    model = env.sim.model._model
    for field in INERTIAL_FIELDS:
        recorded = RECORD[f"{robot}/model/{field}"]
        assert np.max(np.abs(getattr(model, field) - recorded)) <= 1e-6, field


def test_the_controller_gives_mujoco_3_9s_torques_from_the_same_model_and_states(env: Any) -> None:
    robot = type(env.robots[0].robot_model).__name__
    model = env.sim.model._model
    for field in INERTIAL_FIELDS:  # 3.9's compiled inertias: only robosuite's control is compared
        getattr(model, field)[:] = RECORD[f"{robot}/model/{field}"]
    for index, sample in enumerate(_samples(robot)):
        set_state(env, sample)
        torques = arm_torques(env, sample["action"])
        assert np.max(np.abs(torques - sample["torques"])) <= 1e-9, f"{robot} sample {index}"


def test_robosuites_substep_is_one_plain_mujoco_step_bit_for_bit(env: Any) -> None:
    rng = np.random.default_rng(2)
    low, high = (np.clip(bound, -1, 1) for bound in env.action_spec)
    model, data = env.sim.model._model, env.sim.data._data
    for substep in range(10):
        env._pre_action(rng.uniform(low, high), policy_step=substep % 5 == 0)  # what env.step does
        before = {field: np.array(getattr(data, field)) for field in STATE_FIELDS}
        before["time"] = np.array(data.time)
        env.sim.step()
        plain = plain_step(model, before, before["ctrl"])
        assert np.array_equal(plain.qpos, data.qpos) and np.array_equal(plain.qvel, data.qvel)


def test_on_mujoco_3_9_one_plain_step_reproduces_the_recorded_next_states(env: Any) -> None:
    if mujoco.__version__ != str(RECORD["mujoco"]):
        pytest.skip(f"recorded on MuJoCo {RECORD['mujoco']}; MuJoCo {mujoco.__version__}'s physics differ")
    robot = type(env.robots[0].robot_model).__name__
    for sample in _samples(robot):
        after = plain_step(env.sim.model._model, sample, sample["step_ctrl"])
        assert np.array_equal(after.qpos, sample["next_qpos"])
        assert np.array_equal(after.qvel, sample["next_qvel"])
