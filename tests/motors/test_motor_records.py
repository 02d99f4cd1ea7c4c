"""A motor spec is part of what a robot is made from: editing it rebuilds the robots that name it,
through the compiled-model cache and through the request records that answer a repeated request."""

from __future__ import annotations

import os
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

import assembler
from assembler.answers.records import _record_of, keyed
from assembler.compiler.service import wait_for_writes
from tests.conftest import use_private_cache
from tests.motors.rigs import MOTOR, SPINNER_MJCF, motor_yaml


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    folder = use_private_cache(tmp_path / "model-cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    yield folder
    wait_for_writes()


def edit(path: Path, text: str, seconds_ago: float) -> None:
    """Write ``path`` as if some time ago (files changed in the last seconds are not recorded)."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(text)
    then = time.time() - seconds_ago
    os.utime(path, (then, then))


@pytest.fixture
def rig(tmp_path: Path) -> Path:
    """A spec folder: the spinner robot and its motor spec, written an hour ago."""
    folder = tmp_path / "rig"
    edit(folder / "spinner.xml", SPINNER_MJCF.format(extra=""), 3600)
    edit(folder / "motor.yaml", motor_yaml(), 3600)
    edit(
        folder / "robot.yaml",
        "name: Spinner\nmjcf: spinner.xml\nmotors: [{match: spin, motor: TestMotor}]\n",
        3600,
    )
    os.utime(folder, (time.time() - 3600,) * 2)
    return folder


def armature(folder: Path) -> float:
    model = assembler.load_model("Spinner", specs=[folder])
    wait_for_writes()
    return float(model.dof_armature[0])


def answered(folder: Path) -> bool:
    request = {
        "kind": "load_model",
        "robot": "Spinner",
        "idn": 0,
        "base": "default",
        "grippers": None,
        "overrides": None,
        "specs": [str(folder.resolve())],
    }
    return _record_of(keyed(request)) is not None


def test_an_edited_motor_spec_is_a_miss_and_the_robot_is_rebuilt(rig: Path) -> None:
    n = MOTOR["gear_ratio"]
    assert armature(rig) == pytest.approx(MOTOR["rotor_inertia"] * n**2)
    assert answered(rig)
    edit(rig / "motor.yaml", motor_yaml(rotor_inertia=3.0e-5), 30)
    assert not answered(rig)
    assert armature(rig) == pytest.approx(3.0e-5 * n**2)
