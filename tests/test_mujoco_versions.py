"""robosuite's environments run on the installed MuJoCo through the bridge, and the core's floor is the
MuJoCo CI keeps one robosuite stage on.

robosuite 1.5.2's controllers call ``mj_fullM`` with ``MjData.qM`` (gone or changed from MuJoCo
3.10 on); the bridge patches that inside robosuite (``assembler/robosuite/compat.py``), so the
``robosuite`` extra no longer pins MuJoCo. CI's pinned stage installs the core's floor.
"""

from __future__ import annotations

import importlib
import re
from pathlib import Path

import numpy as np
import pytest

PYPROJECT = (Path(__file__).parent.parent / "pyproject.toml").read_text()  # tomllib is 3.11+
CI = (Path(__file__).parent.parent / ".ci" / "run").read_text()


def test_the_core_supports_exactly_down_to_the_mujoco_ci_pins_for_robosuite() -> None:
    (core,) = re.findall(r'^\s*"mujoco>=([0-9.]+)",$', PYPROJECT, flags=re.MULTILINE)
    (pinned,) = set(re.findall(r'"mujoco==([0-9.]+)"', CI))
    assert core == pinned
    assert "mujoco" not in re.findall(r"^robosuite = \[(.*)\]$", PYPROJECT, flags=re.MULTILINE)[0]


def test_a_robosuite_environment_resets_and_steps_on_the_installed_mujoco() -> None:
    robosuite = pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')
    importlib.import_module("assembler.robosuite.bridge")  # patches what this MuJoCo needs
    env = robosuite.make(
        "Lift", robots="Panda", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False
    )
    env.reset()
    for _ in range(10):
        observation, _, _, _ = env.step(np.zeros(env.action_dim))
    assert np.all(np.isfinite(observation["robot0_joint_pos"]))
    env.close()
