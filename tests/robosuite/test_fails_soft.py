"""The bridge fails soft: what a variable names wrongly is one line per problem and robosuite still
imports; a robot without ``init_qpos`` starts at its model's ``qpos0``, said once.

Each case is a real process importing real robosuite (robosuite's registries are module globals).
"""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.processes import result, run, user_folder  # noqa: E402

IMPORTS = """
import json, assembler.robosuite, robosuite  # the start-up hook imports assembler.robosuite the same way
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
print("RESULT " + json.dumps({"Sparrow7": "Sparrow7" in REGISTERED_ROBOTS, "Heron7": "Heron7" in REGISTERED_ROBOTS}))
"""

NOT_REGISTERED = "nothing of it was registered"

BAD_VARIABLES: dict[str, tuple[dict[str, str], list[str]]] = {
    "a missing folder": (
        {"ASSEMBLER_ROBOSUITE_SPECS": "no_such_folder"},
        [f"no such file or folder: no_such_folder (ASSEMBLER_ROBOSUITE_SPECS: {NOT_REGISTERED})"],
    ),
    "a bad spec": (
        {"ASSEMBLER_ROBOSUITE_SPECS": "bad"},
        [
            "bad/broken.yaml:3:13: morphology: Input should be 'manipulator', 'legged_manipulator', "
            f"'humanoid', 'humanoid_upper_body' or 'legged' (ASSEMBLER_ROBOSUITE_SPECS: {NOT_REGISTERED})"
        ],
    ),
    "a name robosuite has": (
        {"ASSEMBLER_ROBOSUITE_SPECS": "my_robots"},
        [
            "my_robots/panda.yaml:4:7: name: robot 'Panda' is already registered by ",
        ],
    ),
    "a missing experiment file": (
        {"ASSEMBLER_ROBOSUITE_EXPERIMENT": "no_such_study.yaml"},
        [
            "no_such_study.yaml: cannot read the file: No such file or directory "
            f"(ASSEMBLER_ROBOSUITE_EXPERIMENT: {NOT_REGISTERED})"
        ],
    ),
}


def _said(stderr: str) -> list[str]:
    """What the assembler printed (robosuite's own log lines start with a bracket)."""
    return [line for line in stderr.splitlines() if line and not line.startswith("[robosuite")]


@pytest.mark.parametrize("case", sorted(BAD_VARIABLES))
def test_a_bad_variable_is_one_line_per_problem_and_robosuite_still_imports(
    case: str, tmp_path: Path
) -> None:
    variables, expected = BAD_VARIABLES[case]
    (tmp_path / "bad").mkdir()
    (tmp_path / "bad" / "broken.yaml").write_text("kind: robot\nname: Broken\nmorphology: nonsense\n")
    user_folder(tmp_path, "Heron7", "Panda")
    done = run(["-c", IMPORTS], tmp_path, **variables)
    assert done.returncode == 0, done.stderr[-3000:]
    said = _said(done.stderr)
    assert len(said) == len(expected)
    for line, start in zip(said, expected, strict=True):
        assert line.startswith(start), line
        assert line.endswith(NOT_REGISTERED + ")")
    (line,) = [line for line in done.stdout.splitlines() if line.startswith("RESULT ")]
    assert '"Sparrow7": true' in line and '"Heron7": false' in line  # the shipped ones, none of the batch


def test_python_m_with_a_bad_variable_prints_the_lines_and_does_not_run_the_script(tmp_path: Path) -> None:
    script = tmp_path / "train.py"
    script.write_text("print('the script ran')\n")
    done = run(
        ["-m", "assembler.robosuite", str(script)],
        tmp_path,
        ASSEMBLER_ROBOSUITE_SPECS="no_such_folder",
        ASSEMBLER_ROBOSUITE_EXPERIMENT="no_such_study.yaml",
    )
    assert done.returncode == 1
    assert "Traceback" not in done.stderr and "the script ran" not in done.stdout
    assert _said(done.stderr) == [
        f"no such file or folder: no_such_folder (ASSEMBLER_ROBOSUITE_SPECS: {NOT_REGISTERED})",
        "no_such_study.yaml: cannot read the file: No such file or directory "
        f"(ASSEMBLER_ROBOSUITE_EXPERIMENT: {NOT_REGISTERED})",
    ]


WITHOUT_INIT_QPOS = """
import json, warnings, numpy as np, robosuite, assembler.robosuite
assembler.robosuite.register("my_robots/")
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    envs = [robosuite.make("Lift", robots="Heron7", has_renderer=False, has_offscreen_renderer=False,
                           use_camera_obs=False, initialization_noise=None) for _ in range(2)]
    starts = []
    for env in envs:
        env.reset()
        starts.append(env.sim.data.qpos[env.robots[0]._ref_joint_pos_indexes].tolist())
        observations, *_ = env.step(np.zeros(env.action_dim))
said = [str(w.message) for w in caught if "init_qpos" in str(w.message)]
print("RESULT " + json.dumps({"said": said, "starts": starts,
                              "finite": bool(np.all(np.isfinite(observations["robot0_joint_pos"])))}))
"""


def test_a_robot_without_init_qpos_starts_at_its_models_qpos0_said_once(tmp_path: Path) -> None:
    folder = user_folder(tmp_path, "Heron7")
    spec = folder / "heron7.yaml"
    text = spec.read_text()
    line = "init_qpos: [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]\n"
    assert line in text
    spec.write_text(text.replace(line, ""))
    seen = result(WITHOUT_INIT_QPOS, tmp_path)
    zeros = [0.0] * 7
    assert seen["said"] == [
        "my_robots/heron7.yaml:4:1: robot 'Heron7' has no init_qpos: robosuite resets its joints to the model "
        f"file's qpos0 {zeros}; set init_qpos in the spec to choose the pose"
    ]
    assert seen["starts"] == [zeros, zeros]
    assert seen["finite"]
