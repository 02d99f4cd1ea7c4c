"""``assembler.assemble`` and ``create_robot`` of a robot asked for before, in a new process: answered
from the cache without importing the schema or reading a spec file, and the robot itself on any
other use. Each script runs twice in new processes sharing one cache: the first makes and records
the robots, the second is answered from the records."""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest

import assembler
from assembler.errors import RegistryError

REPOSITORY = Path(__file__).resolve().parents[2]

HEAVY = '("pydantic", "assembler.models", "assembler.spec.schema")'

COMPILE_ONLY = '("importlib.metadata", "tomllib", "concurrent.futures")'
"""What only a compile, a spec repository's declaration or an install hint needs (~15 ms of imports),
unless MuJoCo's own import brings it (MuJoCo 4.0 imports importlib.metadata)."""

ANSWERED = f"""\
import json, sys
opened = []
sys.addaudithook(lambda event, args: opened.append(str(args[0])) if event == "open" else None)
import mujoco
floor = set(sys.modules)
import assembler
robot = assembler.assemble("Sparrow7", idn=2)
model = robot.get_model()
xml = robot.get_xml()
robot.save(sys.argv[1])
heavy = [name for name in {HEAVY} if name in sys.modules]
unneeded = [name for name in {COMPILE_ONLY} if name in sys.modules and name not in floor]
specs = [path for path in opened if path.endswith((".yaml", ".yml"))]
print(json.dumps({{"heavy": heavy, "unneeded": unneeded, "specs": specs, "nbody": model.nbody, "xml": len(xml)}}))
"""

MADE_ON_USE = f"""\
import copy, json, sys
import numpy as np
import assembler
robot = assembler.assemble("Sparrow7", idn=1)
alone = assembler.create_robot("Sparrow7", 3)
damped = assembler.assemble("Sparrow7", overrides={{"joint_defaults.damping": 0.25}})
models = [robot.get_model(), alone.get_model(), damped.get_model()]
deferred = [type(r).__name__ for r in (robot, alone, damped)]
copied = copy.copy(damped)
heavy = [name for name in {HEAVY} if name in sys.modules]
is_robot = isinstance(robot, assembler.RobotModel)
still_deferred = type(robot).__name__
prefix = robot.naming_prefix
made = type(robot) is assembler.REGISTERED_ROBOTS["Sparrow7"]
compiled = robot.get_model(cache=False)
print(json.dumps({{
    "deferred": deferred,
    "heavy": heavy,
    "is_robot": is_robot,
    "still_deferred": still_deferred,
    "prefix": prefix,
    "made": made,
    "parts": [type(part).__name__ for part in robot.models],
    "home_key": robot.mjspec.key("home") is not None,
    "same_model": bool(
        np.array_equal(compiled.qpos0, models[0].qpos0)
        and np.array_equal(compiled.key_qpos, models[0].key_qpos)
        and compiled.nbody == models[0].nbody
    ),
    "alone": [alone.naming_prefix, len(alone.models), models[1].nbody < models[0].nbody],
    "damping": float(models[2].dof_damping[0]),
    "copied": [copied.get_model().dof_damping[0], copied.naming_prefix],
    "again": type(assembler.assemble("Sparrow7", idn=1)).__name__,
}}))
"""

PATCHED = f"""\
import json, sys
import assembler
assembler.assemble("Sparrow7").get_model()  # the plain robot: cached by the first process
overrides = {{"joint_defaults.armature": 0.2, "joint_defaults.frictionloss": 0.07}}
robot = assembler.assemble("Sparrow7", overrides=overrides)
deferred = type(robot).__name__
model = robot.get_model()
heavy = [name for name in {HEAVY} if name in sys.modules]
compiled = robot.get_model(cache=False)  # made now, with the schema: the full compile
fields = ("dof_armature", "dof_frictionloss", "actuator_biasprm", "dof_invweight0", "key_ctrl")
print(json.dumps({{
    "deferred": deferred,
    "heavy": heavy,
    "values": {{name: getattr(model, name).tolist() for name in fields}},
    "compiled": {{name: getattr(compiled, name).tolist() for name in fields}},
}}))
"""
"""A variant patched from its plain robot's cached model (never stored as a model of its own)."""


def _run(script: str, *arguments: str, cache: Path) -> dict[str, Any]:
    environment = {**os.environ, "PYTHONPATH": str(REPOSITORY), "ASSEMBLER_CACHE_DIR": str(cache)}
    environment.pop("ASSEMBLER_NO_CACHE", None)
    done = subprocess.run(
        [sys.executable, "-c", script, *arguments],
        env=environment,
        capture_output=True,
        text=True,
        check=True,
    )
    return json.loads(done.stdout.splitlines()[-1])  # type: ignore[no-any-return]


def test_a_robot_asked_for_before_is_answered_without_the_schema_or_any_spec_file(tmp_path: Path) -> None:
    first = _run(ANSWERED, str(tmp_path / "first.xml"), cache=tmp_path / "cache")
    second = _run(ANSWERED, str(tmp_path / "second.xml"), cache=tmp_path / "cache")
    assert first["heavy"] and first["specs"]  # the first process read the specs and recorded
    assert second["heavy"] == [] and second["specs"] == []
    assert second["unneeded"] == []
    assert (second["nbody"], second["xml"]) == (first["nbody"], first["xml"])
    assert (tmp_path / "second.xml").read_bytes() == (tmp_path / "first.xml").read_bytes()


def test_a_deferred_robot_becomes_the_robot_it_stands_for_on_any_other_use(tmp_path: Path) -> None:
    first = _run(MADE_ON_USE, cache=tmp_path / "cache")
    second = _run(MADE_ON_USE, cache=tmp_path / "cache")
    assert first["deferred"] == ["Sparrow7"] * 3 and first["heavy"]  # made at once, then recorded
    assert second["deferred"] == ["DeferredRobot"] * 3 and second["heavy"] == []
    for seen in (first, second):
        assert seen["is_robot"] and seen["prefix"] == "robot1_" and seen["made"]
        assert seen["parts"] == ["Pedestal", "PincerGripper"] and seen["home_key"] and seen["same_model"]
        assert seen["alone"] == ["robot3_", 0, True]  # create_robot: no base, no gripper
        assert seen["damping"] == pytest.approx(0.25)
        assert seen["copied"] == [pytest.approx(0.25), "robot0_"]  # a copy is the same robot
        assert seen["again"] == "Sparrow7"  # the model classes are in use now: made at once
    assert second["still_deferred"] == "DeferredRobot"  # isinstance asks the class, makes nothing


def test_an_unknown_robot_is_an_error_when_assembled() -> None:
    with pytest.raises(RegistryError, match="unknown robot 'Sparow7'. Did you mean 'Sparrow7'"):
        assembler.assemble("Sparow7")
    with pytest.raises(RegistryError, match="unknown robot 'Sparow7'"):
        assembler.create_robot("Sparow7")


def test_a_patched_variant_asked_for_before_is_answered_without_the_schema(tmp_path: Path) -> None:
    first = _run(PATCHED, cache=tmp_path / "cache")
    assert list((tmp_path / "cache").glob("*.patch"))  # its patch kept in place of a model
    second = _run(PATCHED, cache=tmp_path / "cache")
    assert first["heavy"] and first["deferred"] == "Sparrow7"
    assert second["heavy"] == [] and second["deferred"] == "DeferredRobot"
    for seen in (first, second):
        for name, values in seen["compiled"].items():
            assert np.allclose(seen["values"][name], values, rtol=1e-10, atol=1e-10), name
    assert second["values"] == first["values"]
    assert second["values"]["dof_frictionloss"][0] == pytest.approx(0.07)
