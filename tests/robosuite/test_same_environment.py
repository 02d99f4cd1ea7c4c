"""robosuite's robots built from our specs make the same environments as robosuite's own.

Each case runs one environment twice, each in its own process (``record_env.py``): with robosuite's
classes, and with robosuite's robots, grippers and bases replaced by our specs. The compiled worlds
are compared field by field with the parity oracle (tests/parity), which allows exactly the
deviations docs/robosuite-parity.md documents (D1: a mobile base's mount body carries the robot's
prefix; D2: a legged base's mount body is ours only); the observations and rewards over 200 seeded
random steps must be identical, bit for bit.
"""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import mujoco
import numpy as np
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.parity.oracle import differences  # noqa: E402
from tests.parity.robosuite_side import Reference  # noqa: E402

# A parity case (robosuite's own robots against our specs of them, on one MuJoCo): CI runs it once, on
# the newest MuJoCo, with the other parity cases; on 3.9 robosuite's own suite runs its environments.
pytestmark = pytest.mark.parity

ROOT = Path(__file__).resolve().parents[2]
STEPS = 200

ENVIRONMENTS = [
    ("Lift", "Panda"),
    ("Stack", "Panda"),
    ("Door", "Panda"),
    ("Wipe", "Panda"),
    ("PickPlace", "Panda"),
]
ENVIRONMENTS += [("TwoArmLift", "Panda,Panda"), ("TwoArmHandover", "Panda,Panda")]
ENVIRONMENTS += [("TwoArmLift", "Baxter"), ("TwoArmHandover", "Baxter")]
ROBOTS_IN_LIFT = ["IIWA", "Sawyer", "Jaco", "Kinova3", "UR5e", "XArm7", "PandaDexRH", "GR1ArmsOnly"]
ROBOTS_IN_LIFT += ["Tiago", "PandaOmron", "SpotWithArm"]
CASES = ENVIRONMENTS + [("Lift", robot) for robot in ROBOTS_IN_LIFT]

MOUNT_RENAMED = {
    "Tiago": "manipulator_mount",
    "PandaOmron": "manipulator_mount",
    "GR1ArmsOnly": "manipulator_mount",
    "SpotWithArm": None,
}
"""D1 and D2 (docs/robosuite-parity.md): the body robosuite's add_mobile_base/add_leg_base adds."""


def _record(side: str, env: str, robots: str, out: Path) -> tuple[mujoco.MjModel, dict[str, np.ndarray]]:
    environment = {**os.environ, "MUJOCO_GL": "egl", "PYTHONPATH": str(ROOT)}
    command = [sys.executable, "-m", "tests.robosuite.record_env", side, env, robots, str(STEPS), str(out)]
    done = subprocess.run(command, cwd=ROOT, env=environment, capture_output=True, text=True, check=False)
    assert done.returncode == 0, f"{side} {env} {robots}:\n{done.stderr[-3000:]}"
    with np.load(f"{out}.npz") as recorded:
        return mujoco.MjModel.from_binary_path(f"{out}.mjb"), dict(recorded)


@pytest.mark.parametrize(("env", "robots"), CASES, ids=[f"{env}-{robots}" for env, robots in CASES])
def test_our_specs_make_robosuites_environment(env: str, robots: str, tmp_path: Path) -> None:
    stock, stock_steps = _record("stock", env, robots, tmp_path / "stock")
    specs, spec_steps = _record("specs", env, robots, tmp_path / "specs")
    renamed = {"robot0_manipulator_mount": MOUNT_RENAMED[robots]} if robots in MOUNT_RENAMED else {}
    nothing = np.zeros(0)
    found = differences(specs, Reference(stock, nothing, nothing), renamed)
    found = [line for line in found if not line.startswith("keyframe ")]  # environments have none
    expected = (
        [
            f"body robot0_manipulator_mount: {'named manipulator_mount in robosuite' if MOUNT_RENAMED.get(robots) else 'not in robosuite'}"
        ]
        if robots in MOUNT_RENAMED
        else []
    )
    assert found == expected
    assert sorted(spec_steps) == sorted(stock_steps)
    unequal = [key for key in stock_steps if not np.array_equal(spec_steps[key], stock_steps[key])]
    assert unequal == [], f"{len(unequal)} observations differ, first {unequal[0]}" if unequal else ""
