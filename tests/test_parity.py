"""Parity with robosuite 1.5.2: what we assemble from YAML compiles to robosuite's own model.

Each case assembles the same robot, base and grippers both ways and compares the compiled models
field by field (tests/robosuite_reference.py). Deviations are allowed only where robosuite is
demonstrably wrong, listed in docs/robosuite-parity.md, and checked here exactly.
"""

from __future__ import annotations

import numpy as np
import pytest

import assembler
from tests.robosuite_reference import differences, robosuite_model

pytest.importorskip("robosuite", reason='parity needs robosuite: pip install ".[test,robosuite]"')

ROBOTS_WITH_DEFAULTS = ["Panda", "Sawyer"]

CASES = [pytest.param(robot, "default", None, id=robot) for robot in ROBOTS_WITH_DEFAULTS]

DEVIATIONS: dict[str, list[str]] = {}
"""Per case id, the differences we keep on purpose (each explained in docs/robosuite-parity.md)."""


@pytest.mark.parametrize(("robot", "base", "gripper"), CASES)
def test_parity_with_robosuite(
    robot: str, base: str, gripper: str | None, request: pytest.FixtureRequest
) -> None:
    arms = assembler.REGISTERED_ROBOTS[robot].spec.arms
    grippers = dict.fromkeys(arms, gripper) if gripper else None
    ours = assembler.assemble(robot, idn=0, base=base, grippers=grippers).get_model()
    reference = robosuite_model(robot, base=base, grippers=grippers)
    case = request.node.callspec.id
    assert differences(ours, reference) == DEVIATIONS.get(case, [])


def test_the_oracle_notices_a_changed_joint_and_a_moved_gripper() -> None:
    robot = assembler.assemble("Panda", idn=0)
    robot.set_joint_attribute("damping", np.full(robot.dof, 0.3))
    robot.mjspec.body("gripper0_right_right_gripper").pos = [0.0, 0.0, 0.01]
    found = differences(robot.get_model(), robosuite_model("Panda"))
    assert "joint robot0_joint1: damping [0.3] != [0.1]" in found
    assert "body gripper0_right_right_gripper: world position differs" in found
