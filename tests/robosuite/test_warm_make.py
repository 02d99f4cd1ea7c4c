"""Make records: a process whose specs did not change makes robosuite's environments without reading
the specs of the parts it makes (nor importing pydantic or the spec classes), and simulates what a
process that read them simulates.

Each case runs in its own Python process (robosuite's tables are module globals) with its own cache
folder: the first process records the registrations, the second the makes, the third is answered.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.processes import LIFT_STEPPED, result  # noqa: E402

MAKE_AND_STEP = (
    LIFT_STEPPED
    + """
import json, sys
import numpy as np
import assembler.robosuite
import robosuite
from assembler.models import REGISTRIES

assembler.robosuite.replace_robosuite()
observed, unread = {}, {}
for robot in ("Panda", "Sparrow7"):
    env, observed[robot] = lift_stepped(robot)
    unread[robot] = sorted(f"{family}:{name}" for family, table in REGISTRIES.items() for name in table.held_names())
    if robot == "Panda":
        # what is imported before anything asks for our part itself
        schema = sorted(name for name in sys.modules if name == "pydantic" or name.startswith("assembler.spec.schema"))
        # anything not recorded is our part itself: made now, with its base and gripper
        model = env.robots[0].robot_model
        gripper = env.robots[0].gripper["right"]
        made = {
            "robot": type(model.assembly).__name__,
            "base": type(model.assembly.base).__name__,
            "same_gripper": model.assembly.grippers["right"] is gripper.part,
            "same_base": model.assembly.base is model.base.part,
            "arm_joints": list(model.assembly.arm_joints),
            "after": sorted(f"{family}:{name}" for family, table in REGISTRIES.items() for name in table.held_names()),
        }
    env.close()
print("RESULT " + json.dumps({"observed": observed, "unread": unread, "made": made, "schema": schema}))
"""
)

PANDAS = {"robot:Panda", "gripper:PandaGripper", "base:RethinkMount"}
"""What Lift with Panda is made of (robosuite's names, our specs replacing them)."""


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    cwd, cache = tmp_path_factory.mktemp("warm-make"), tmp_path_factory.mktemp("warm-make-cache")

    def run(cache: Path | None) -> Any:
        variables = {"ASSEMBLER_CACHE_DIR": str(cache)} if cache else {"ASSEMBLER_NO_CACHE": "1"}
        return result(MAKE_AND_STEP, cwd, **variables)

    return {"off": run(None), "first": run(cache), "second": run(cache), "warm": run(cache)}


def test_a_warm_make_reads_none_of_the_specs_it_makes(runs: dict[str, Any]) -> None:
    assert set(runs["warm"]["unread"]["Panda"]) >= PANDAS
    assert {"robot:Sparrow7", "gripper:PincerGripper"} <= set(runs["warm"]["unread"]["Sparrow7"])
    assert not PANDAS & set(runs["off"]["unread"]["Panda"])  # with the cache off, all three are read


def test_a_warm_make_imports_neither_pydantic_nor_the_spec_classes(runs: dict[str, Any]) -> None:
    assert runs["warm"]["schema"] == []
    assert "pydantic" in runs["off"]["schema"]  # the cache off reads the specs: the schema is there


def test_a_warm_make_simulates_what_a_process_that_reads_the_specs_simulates(runs: dict[str, Any]) -> None:
    for run in ("first", "second", "warm"):
        assert runs[run]["observed"] == runs["off"]["observed"], run


def test_our_part_is_made_when_asked_for_with_what_robosuite_gave_it(runs: dict[str, Any]) -> None:
    warm, off = runs["warm"]["made"], runs["off"]["made"]
    assert warm["robot"] == "Panda" and warm["base"] == "RethinkMount"
    assert warm["same_gripper"] and warm["same_base"]
    assert warm["arm_joints"] == off["arm_joints"]
    assert not PANDAS & set(warm["after"])  # read now, for the part asked for
