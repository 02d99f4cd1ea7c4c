"""Our own robots, which robosuite has never seen, in robosuite's environments.

Each case makes the environment with ``import assembler.robosuite`` as the only preparation (the
robot's default controller, no cameras), resets it, runs 200 steps of random actions within
``action_spec`` and checks that every observation is finite and that the robot's joints moved.
Single-arm robots run every single-arm environment robosuite 1.5.2 ships (``ALL_ENVIRONMENTS``
without the TwoArm ones, the PickPlace and NutAssembly variants included); TwinTorso, bimanual, runs
every TwoArm environment as one robot (``env_configuration="single-robot"``); the URDF arms of
example-robot-data run Lift when it is installed. A scripted pick shows a user's first experiment
works: Sparrow7 with its gripper lifts Lift's cube with robosuite's OSC_POSE controller.
"""

from __future__ import annotations

import warnings
from pathlib import Path
from typing import Any

import numpy as np
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

import robosuite  # noqa: E402
from robosuite.robots import ROBOT_CLASS_MAPPING  # noqa: E402

import assembler.robosuite  # noqa: E402, F401
from assembler.errors import AssemblerWarning, SpecError  # noqa: E402
from assembler.models import REGISTERED_ROBOTS  # noqa: E402
from assembler.robosuite.robot_class import robot_class  # noqa: E402
from assembler.urdf.packages import package_folders  # noqa: E402
from tests.robosuite.processes import result  # noqa: E402

STEPS = 200
SINGLE_ARM_ENVIRONMENTS = [env for env in robosuite.ALL_ENVIRONMENTS if not env.startswith("TwoArm")]
TWO_ARM_ENVIRONMENTS = [env for env in robosuite.ALL_ENVIRONMENTS if env.startswith("TwoArm")]
CASES = [(env, robot) for robot in ("Sparrow7", "Finch6") for env in SINGLE_ARM_ENVIRONMENTS]
CASES += [(env, "TwinTorso") for env in TWO_ARM_ENVIRONMENTS]


needs_urdf_robots = pytest.mark.skipif(
    not package_folders("example-robot-data"), reason='needs example-robot-data: pip install ".[urdf]"'
)


def _make(env_name: str, robots: str, **options: Any) -> Any:
    if env_name.startswith("TwoArm"):
        options.setdefault("env_configuration", "single-robot")
    options.setdefault("horizon", STEPS)
    return robosuite.make(
        env_name,
        robots=robots,
        has_renderer=False,
        has_offscreen_renderer=False,
        use_camera_obs=False,
        **options,
    )


def _random_steps(env_name: str, robots: str) -> tuple[np.ndarray, dict[str, Any], Any]:
    """The robot's largest joint displacement over the random steps, the last observations, the env."""
    env = _make(env_name, robots)
    env.reset()
    robot = env.robots[0]
    start = env.sim.data.qpos[robot._ref_joint_pos_indexes].copy()
    low, high = env.action_spec
    rng = np.random.default_rng(0)
    for _ in range(STEPS):
        observations, _, _, _ = env.step(rng.uniform(low, high))
    moved = np.abs(env.sim.data.qpos[robot._ref_joint_pos_indexes] - start)
    return moved, observations, env


def _check_runs(env_name: str, robots: str) -> None:
    moved, observations, env = _random_steps(env_name, robots)
    try:
        not_finite = [
            key
            for key, value in observations.items()
            if not np.all(np.isfinite(np.asarray(value, dtype=float)))
        ]
        assert not not_finite, f"observations not finite after {STEPS} steps: {not_finite}"
        assert moved.max() > 0.05, f"the joints of {robots} did not move: {moved}"
    finally:
        env.close()


@pytest.mark.parametrize(("env_name", "robots"), CASES, ids=[f"{env}-{robot}" for env, robot in CASES])
def test_our_robot_runs_robosuites_environment_with_random_actions(env_name: str, robots: str) -> None:
    _check_runs(env_name, robots)


SAID_IN_A_NEW_PROCESS = """
import json, warnings
import assembler.robosuite, robosuite
from assembler.errors import AssemblerWarning
kwargs = dict(has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("default")
    for _ in range(2):
        robosuite.make("Lift", robots="{robot}", **kwargs).close()
notes = [str(w.message) for w in caught if issubclass(w.category, AssemblerWarning)]
print("RESULT " + json.dumps([note for note in notes if "right_center" in note]))
"""


@needs_urdf_robots
@pytest.mark.parametrize("robot", ["UR5", "SO101"])
def test_a_urdf_arm_runs_lift_with_a_center_site_added_and_said_once_per_process(
    robot: str, tmp_path: Path
) -> None:
    with warnings.catch_warnings():  # said once per process: perhaps by an earlier test of this one
        warnings.simplefilter("ignore", AssemblerWarning)
        _check_runs("Lift", robot)
    (said,) = result(SAID_IN_A_NEW_PROCESS.format(robot=robot), tmp_path)  # two makes, one note
    assert "read the site right_center, which the model file lacks" in said


@needs_urdf_robots
def test_frankapanda_whose_arm_group_holds_a_mimic_finger_is_not_offered_and_refused_with_the_reason() -> (
    None
):
    assert "FrankaPanda" not in ROBOT_CLASS_MAPPING  # its spec says robosuite.enabled: false, and why
    expected = (
        "franka_panda.yaml:9:3: joint_groups: robosuite's controllers drive each joint of the groups they "
        "control with one actuator, but panda_finger_joint2 has none (a mimic follower?): declare an "
        "actuator for each, or set robosuite.enabled: false for a robot robosuite cannot drive"
    )
    with pytest.raises(SpecError) as error:
        robot_class(REGISTERED_ROBOTS.lookup("FrankaPanda"))(idn=0)
    assert str(error.value).endswith(expected)
    assert "\n" not in str(error.value)


def _pick(env: Any, observations: dict[str, Any]) -> dict[str, Any]:
    """Move the gripper above the cube, descend, close, lift: a position loop on OSC_POSE's deltas."""

    def move(target: np.ndarray, grip: float, steps: int, tolerance: float | None = 0.005) -> None:
        nonlocal observations
        for _ in range(steps):
            error = target - observations["robot0_eef_pos"]
            if tolerance is not None and np.linalg.norm(error) < tolerance:
                return
            action = np.zeros(env.action_dim)
            action[:3] = np.clip(10 * error, -1, 1)
            action[-1] = grip  # robosuite's convention: -1 opens, +1 closes
            observations, _, _, _ = env.step(action)

    cube = observations["cube_pos"].copy()
    move(cube + [0, 0, 0.10], grip=-1, steps=300)
    move(cube, grip=-1, steps=200)
    move(observations["robot0_eef_pos"].copy(), grip=1, steps=30, tolerance=None)
    move(cube + [0, 0, 0.20], grip=1, steps=200)
    return observations


def test_sparrow7_with_its_gripper_lifts_the_cube_in_lift_with_osc_pose() -> None:
    config = robosuite.load_composite_controller_config(controller="BASIC")
    config["body_parts"]["right"]["type"] = "OSC_POSE"
    env = _make("Lift", "Sparrow7", controller_configs=config, horizon=1000, ignore_done=True)
    try:
        observations = env.reset()
        start = observations["cube_pos"][2]
        observations = _pick(env, observations)
        rise = observations["cube_pos"][2] - start
        assert rise > 0.05, f"the cube rose {rise:.3f} m"
        assert env._check_success(), "Lift's own success check says the cube is not lifted"
    finally:
        env.close()


def test_the_gripper_and_base_robosuite_read_are_the_parts_our_assembly_holds() -> None:
    env = _make("Lift", "Sparrow7")
    try:
        robot = env.robots[0]
        model = robot.robot_model
        gripper = robot.gripper["right"]
        assert model.assembly.grippers["right"] is gripper.part  # its model file read once, for both
        assert model.assembly.base is model.base.part
    finally:
        env.close()
