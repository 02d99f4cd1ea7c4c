"""Registration records: a process whose shipped specs did not change puts them in robosuite's tables
without reading one, and what it registers and simulates is what a process that read them does.

Each case runs in its own Python process (robosuite's tables are module globals) with its own cache
folder: the first process reads the specs and records them, the next is answered from the records.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.processes import LIFT_STEPPED, result  # noqa: E402

REGISTER_AND_RUN = (
    LIFT_STEPPED
    + """
import json, sys
import numpy as np
import robosuite
import assembler.robosuite
from assembler.models import REGISTRIES
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.robots import ROBOT_CLASS_MAPPING
from robosuite.models.grippers import GRIPPER_MAPPING
from robosuite.models.bases import BASE_MAPPING

replaced = assembler.robosuite.replace_robosuite()
unread = sorted(f"{family}:{name}" for family, table in REGISTRIES.items() for name in table.held_names())
ours = lambda table: {str(n): [c.__name__, [b.__name__ for b in c.__mro__[1:3]]] for n, c in table.items()
                      if getattr(c, "__module__", "").startswith("assembler.")}
tables = {
    "robots": {n: [c.arms, getattr(ROBOT_CLASS_MAPPING.get(n), "__name__", None)] for n, c in REGISTERED_ROBOTS.items()
               if c.__module__.startswith("assembler.")},
    "grippers": ours(GRIPPER_MAPPING),
    "bases": ours(BASE_MAPPING),
}
observed = {}
for robot in ("Panda", "Sparrow7"):
    env, observed[robot] = lift_stepped(robot)
    env.close()
print("RESULT " + json.dumps({"replaced": replaced, "unread": unread, "tables": tables, "observed": observed}))
"""
)


def _run(cwd: Path, cache: Path | None) -> Any:
    variables = {"ASSEMBLER_CACHE_DIR": str(cache)} if cache is not None else {"ASSEMBLER_NO_CACHE": "1"}
    return result(REGISTER_AND_RUN, cwd, **variables)


@pytest.fixture(scope="module")
def runs(tmp_path_factory: pytest.TempPathFactory) -> dict[str, Any]:
    cwd, cache = tmp_path_factory.mktemp("records"), tmp_path_factory.mktemp("records-cache")
    return {"read": _run(cwd, None), "first": _run(cwd, cache), "warm": _run(cwd, cache)}


def test_a_warm_process_registers_and_replaces_every_shipped_spec_without_reading_one(
    runs: dict[str, Any],
) -> None:
    # the records answer the bridge's import and replace_robosuite(): every shipped name stays held
    # (its spec unread) after both; a process without the cache reads every one it installs
    warm, read = runs["warm"], runs["read"]
    assert {"robot:Panda", "robot:Sparrow7", "gripper:PandaGripper", "base:Pedestal"} <= set(warm["unread"])
    assert sorted(warm["replaced"]) == sorted(read["replaced"])
    installed = {f"robot:{name}" for name in read["tables"]["robots"]}
    installed |= {f"gripper:{name}" for name in read["tables"]["grippers"] if name != "None"}
    installed |= {f"base:{name}" for name in read["tables"]["bases"]}
    assert installed - {"gripper:NullGripper"} <= set(warm["unread"])
    assert not set(read["unread"]) & installed


def test_a_warm_process_registers_what_a_process_that_reads_the_specs_registers(runs: dict[str, Any]) -> None:
    assert runs["warm"]["tables"] == runs["read"]["tables"]
    assert runs["first"]["tables"] == runs["read"]["tables"]


def test_a_warm_process_simulates_lift_as_a_process_that_reads_the_specs(runs: dict[str, Any]) -> None:
    # Panda replaced by its spec, Sparrow7 a spec robosuite does not have: both read when made
    assert runs["warm"]["observed"] == runs["read"]["observed"]
    assert runs["first"]["observed"] == runs["read"]["observed"]
