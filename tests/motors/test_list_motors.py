"""`assembler list motors`: every motor spec by name, with its gear ratio, torque limit and reflected
inertia with its own gearbox, and the file it was read from."""

from __future__ import annotations

import pytest

from assembler.cli import main
from assembler.models.motor_table import MOTORS


def test_list_motors_shows_every_motor_with_its_limit_and_armature(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["list", "motors"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].split() == [
        "motor",
        "gear",
        "ratio",
        "torque",
        "limit",
        "(N",
        "m)",
        "armature",
        "(kg",
        "m2)",
        "spec",
    ]
    rows = {line.split()[0]: line.split() for line in lines[1:] if line.strip()}
    assert set(rows) == set(MOTORS.names())
    go2_hip = rows["UnitreeGo2HipMotor"]
    assert go2_hip[1:4] == ["6", "23.7", f"{0.000111842 * 36:.4g}"]
    assert " ".join(go2_hip[4:]) == "specs/motors/unitree_go2.yaml (shipped)"
