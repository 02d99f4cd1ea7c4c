"""``assembler.assemble`` and ``create_robot`` of a robot asked for before: answered from the cache
without importing the schema or reading a spec file, and the robot itself on any other use."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from collections.abc import Iterator
from pathlib import Path

import numpy as np
import pytest

import assembler
from assembler.build.service import wait_for_writes
from assembler.errors import RegistryError
from assembler.registry.deferred import DeferredRobot
from tests.conftest import use_private_cache

REPOSITORY = Path(__file__).resolve().parents[2]

USER_SCRIPT = """\
import json, sys
opened = []
sys.addaudithook(lambda event, args: opened.append(str(args[0])) if event == "open" else None)
import assembler
robot = assembler.assemble("Sparrow7", idn=2)
model = robot.get_model()
xml = robot.get_xml()
robot.save(sys.argv[1])
heavy = [name for name in ("pydantic", "assembler.models", "assembler.spec.schema") if name in sys.modules]
specs = [path for path in opened if path.endswith((".yaml", ".yml"))]
print(json.dumps({"heavy": heavy, "specs": specs, "nbody": model.nbody, "xml": len(xml)}))
"""


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    folder = use_private_cache(tmp_path / "model-cache", monkeypatch)
    yield folder
    wait_for_writes()


def _run_user_script(output: Path) -> dict[str, object]:
    environment = {**os.environ, "PYTHONPATH": str(REPOSITORY)}
    done = subprocess.run(
        [sys.executable, "-c", USER_SCRIPT, str(output)],
        env=environment,
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(done.stdout.splitlines()[-1])  # type: ignore[no-any-return]


def test_a_robot_asked_for_before_is_answered_without_the_schema_or_any_spec_file(tmp_path: Path) -> None:
    first = _run_user_script(tmp_path / "first.xml")
    second = _run_user_script(tmp_path / "second.xml")
    assert first["heavy"] and first["specs"]  # the first process read the specs and recorded
    assert second["heavy"] == [] and second["specs"] == []
    assert (second["nbody"], second["xml"]) == (first["nbody"], first["xml"])
    assert (tmp_path / "second.xml").read_bytes() == (tmp_path / "first.xml").read_bytes()


def test_a_deferred_robot_becomes_the_robot_it_stands_for_on_any_other_use() -> None:
    made = assembler.assemble("Sparrow7", idn=1)
    made.get_model()
    wait_for_writes()
    robot = assembler.assemble("Sparrow7", idn=1)
    assert type(robot) is DeferredRobot
    model = robot.get_model()
    sparrow = assembler.REGISTERED_ROBOTS["Sparrow7"]
    assert isinstance(robot, assembler.RobotModel) and isinstance(robot, sparrow)
    assert robot.naming_prefix == "robot1_"
    assert type(robot) is sparrow
    assert [type(part).__name__ for part in robot.models] == [type(part).__name__ for part in made.models]
    assert robot.mjspec.key("home") is not None  # the keyframe of the model it handed out
    compiled = robot.get_model(cache=False)
    np.testing.assert_array_equal(compiled.qpos0, model.qpos0)
    np.testing.assert_array_equal(compiled.key_qpos, model.key_qpos)
    assert compiled.nbody == model.nbody


def test_create_robot_and_overrides_are_requests_of_their_own() -> None:
    overrides = {"joint_defaults.damping": 0.25}
    for _ in range(2):
        alone = assembler.create_robot("Sparrow7", 3)
        damped = assembler.assemble("Sparrow7", overrides=overrides)
        alone_model, damped_model = alone.get_model(), damped.get_model()
        wait_for_writes()
    assert type(alone) is DeferredRobot and type(damped) is DeferredRobot
    assert alone_model.nbody < damped_model.nbody  # no base, no gripper
    assert alone.naming_prefix == "robot3_" and alone.models == []
    assert damped_model.dof_damping[0] == pytest.approx(0.25)


def test_an_unknown_robot_is_an_error_when_assembled() -> None:
    with pytest.raises(RegistryError, match="unknown robot 'Sparow7'. Did you mean 'Sparrow7'"):
        assembler.assemble("Sparow7")
    with pytest.raises(RegistryError, match="unknown robot 'Sparow7'"):
        assembler.create_robot("Sparow7")
