"""The MuJoCo the ``robosuite`` extra pins runs robosuite's own environments, and the core's floor is it.

robosuite 1.5.2's controllers call ``mj_fullM`` with ``MjData.qM`` (gone or changed from MuJoCo
3.10 on), so a bump of the pin past 3.9 breaks every robosuite environment; this test notices.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np
import pytest

PYPROJECT = (Path(__file__).parent.parent / "pyproject.toml").read_text()  # tomllib is 3.11+


def test_the_core_supports_exactly_down_to_the_mujoco_the_robosuite_extra_pins() -> None:
    (core,) = re.findall(r'^\s*"mujoco>=([0-9.]+)",$', PYPROJECT, flags=re.MULTILINE)
    (pinned,) = re.findall(r'^robosuite = \[.*"mujoco==([0-9.]+)".*\]$', PYPROJECT, flags=re.MULTILINE)
    assert core == pinned


def test_a_robosuite_environment_resets_and_steps_on_the_installed_mujoco() -> None:
    robosuite = pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')
    env = robosuite.make(
        "Lift", robots="Panda", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False
    )
    env.reset()
    for _ in range(10):
        observation, _, _, _ = env.step(np.zeros(env.action_dim))
    assert np.all(np.isfinite(observation["robot0_joint_pos"]))
    env.close()
