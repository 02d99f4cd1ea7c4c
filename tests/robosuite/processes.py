"""Python processes for the bridge's tests: robosuite's registries are module globals, so a case that
registers runs in its own interpreter (this checkout first on ``PYTHONPATH``) and reports what it saw
as one ``RESULT <json>`` line."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]
VARIABLES = ("ASSEMBLER_ROBOSUITE_SPECS", "ASSEMBLER_ROBOSUITE_EXPERIMENT")
RESULT = "RESULT "


LIFT_STEPPED = """
def lift_stepped(robot):
    \"\"\"robosuite's Lift with ``robot``, reset, then 10 steps of one action: the environment and its
    last observations, rounded to 9 digits (the seed places the cube).\"\"\"
    env = robosuite.make("Lift", robots=robot, has_renderer=False, has_offscreen_renderer=False,
                         use_camera_obs=False, seed=0)
    env.reset()
    action = np.full(env.action_dim, 0.1)
    for _ in range(10):
        obs, _, _, _ = env.step(action)
    return env, {key: np.asarray(value).round(9).tolist() for key, value in sorted(obs.items())}
"""
"""A script's function (it needs ``numpy as np`` and ``robosuite`` imported) that makes and steps Lift
the same way in every process whose observations a test compares."""


def environment(**variables: str) -> dict[str, str]:
    environment = {key: value for key, value in os.environ.items() if key not in VARIABLES}
    paths = [str(ROOT), *filter(None, environment.get("PYTHONPATH", "").split(os.pathsep))]
    return {**environment, "PYTHONPATH": os.pathsep.join(paths), "MUJOCO_GL": "egl", **variables}


def run(
    args: list[str], cwd: Path, python: str = sys.executable, **variables: str
) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [python, *args], cwd=cwd, env=environment(**variables), capture_output=True, text=True, check=False
    )


def result(code: str, cwd: Path, **variables: str) -> Any:
    """What the script prints as ``RESULT <json>`` (it fails the test if the script fails)."""
    done = run(["-c", textwrap.dedent(code)], cwd, **variables)
    assert done.returncode == 0, done.stderr[-3000:]
    (line,) = [line for line in done.stdout.splitlines() if line.startswith(RESULT)]
    return json.loads(line[len(RESULT) :])


def user_folder(root: Path, *names: str) -> Path:
    """A user's spec folder ``root/my_robots``: Sparrow7's spec copied under each name, its model file
    copied into the folder (a spec reads files in its own folder) and ``mjcf:`` pointed at it."""
    folder = root / "my_robots"
    folder.mkdir(exist_ok=True)
    shutil.copytree(ROOT / "assets" / "sparrow7", folder / "assets", dirs_exist_ok=True)
    text = (ROOT / "specs" / "sparrow7.yaml").read_text()
    for old, new in (
        ("\nname: Sparrow7\n", "\nname: NAME\n"),
        ("\nmjcf: ../assets/sparrow7/", "\nmjcf: assets/"),
    ):
        assert old in text
        text = text.replace(old, new)
    for name in names:
        (folder / f"{name.lower()}.yaml").write_text(text.replace("\nname: NAME\n", f"\nname: {name}\n"))
    return folder
