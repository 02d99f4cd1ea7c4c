"""Parity with robosuite 1.5.2: what we assemble from YAML compiles to robosuite's own model.

Each case assembles the same robot, base and grippers both ways, as a user would (another idn,
placement, joint attributes included), compiles both and compares them element by element and
field by field (tests/parity/oracle.py). Differences are allowed only where robosuite is
demonstrably wrong; each is explained in docs/robosuite-parity.md and checked here exactly, case by
case. The cases take minutes: ``pytest -m "not parity"`` leaves them out.
"""

from __future__ import annotations

from typing import Any

import numpy as np
import pytest

import assembler
from tests.parity import report
from tests.parity.case import Case, build_ours
from tests.parity.cases import ALL, BASES, GRIPPERS, ROBOTS, expected, renamed, same_assemblies
from tests.parity.oracle import differences
from tests.parity.robosuite_side import Reference, build_reference, normalized

pytest.importorskip("robosuite", reason='parity needs robosuite: pip install ".[test,robosuite]"')
pytestmark = pytest.mark.parity


def test_every_robosuite_robot_gripper_and_base_has_a_spec() -> None:
    from robosuite.models.bases import BASE_MAPPING
    from robosuite.models.grippers import GRIPPER_MAPPING
    from robosuite.models.robots.robot_model import REGISTERED_ROBOTS

    def robosuites(table: dict[Any, type]) -> list[Any]:
        # robosuite's own: not ours (a test may have imported assembler.robosuite), nor those of a
        # package that registers with robosuite when it loads (robosuite-models, the corpus extra)
        return [name for name, cls in table.items() if cls.__module__.split(".")[0] == "robosuite"]

    robots = sorted(
        set(robosuites(REGISTERED_ROBOTS)) - {"LeggedManipulatorModel"}
    )  # abstract, yet registered
    assert robots == ROBOTS and len(ROBOTS) == 19
    grippers = sorted(name or "NullGripper" for name in robosuites(GRIPPER_MAPPING))
    assert grippers == GRIPPERS and len(GRIPPERS) == 16
    assert sorted(name or "NullBase" for name in robosuites(BASE_MAPPING)) == BASES and len(BASES) == 10


GROUPS = same_assemblies(ALL)


@pytest.mark.parametrize("cases", GROUPS, ids=[" = ".join(case.id for case in group) for group in GROUPS])
def test_our_model_equals_robosuites_but_for_its_documented_deviations(cases: list[Case]) -> None:
    """Cases that assemble the same thing (Panda, and Panda with PandaGripper) share robosuite's
    compile when robosuite's defaults make them equal too; each is built and compared on our side."""
    references: dict[Case, Reference] = {}
    for case in cases:
        key = normalized(case)
        if key not in references:
            references[key] = build_reference(key)
        reference = references[key]
        found = differences(build_ours(case), reference, renamed(case))
        assert sorted(found) == expected(case), case.id


@pytest.mark.parametrize("robot", ["GR1ArmsOnly", "GR1FixedLowerBody", "GR1FloatingBody"])
def test_robosuite_cannot_set_joint_attributes_of_a_gr1_without_legs_and_we_can(robot: str) -> None:
    """D6: robosuite removes these robots' leg (and head) joints from the MJCF but not from the
    joint list ``set_joint_attribute`` checks and walks, so any call fails."""
    from robosuite.models.robots import create_robot

    theirs = create_robot(robot, idn=0)
    with pytest.raises(AssertionError, match=rf"Got {theirs.dof}, expected {theirs.dof}!"):
        theirs.set_joint_attribute("frictionloss", np.full(theirs.dof, 0.3))
    ours = assembler.assemble(robot, idn=0)
    ours.set_joint_attribute("frictionloss", np.full(ours.dof, 0.3))
    model = ours.get_model()
    assert [model.joint(j).frictionloss[0] for j in ours.joints] == [0.3] * theirs.dof


def test_the_parity_document_shows_the_results_of_these_cases() -> None:
    committed = report.DOC.read_text()
    assert committed == report.rendered(committed), (
        f"docs/robosuite-parity.md is out of date; regenerate it with: {report.COMMAND}"
    )
