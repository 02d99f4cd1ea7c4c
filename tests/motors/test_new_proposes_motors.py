"""`assembler new` on a file without actuators names the shipped motors whose torque limit is a
joint's effort limit, as something to decide (it writes no motor the file does not name)."""

from __future__ import annotations

from pathlib import Path

import yaml

from assembler.importers import new_spec
from assembler.models.motor_table import MOTORS
from tests.conftest import TWO_LINK_MJCF
from tests.motors.rigs import Write

BARE = TWO_LINK_MJCF.split("  <actuator>")[0] + "</mujoco>\n"
"""The two-link arm without actuators."""


def test_new_names_the_shipped_motors_whose_torque_limit_is_a_joints_effort_limit(write: Write) -> None:
    limited = BARE.replace('range="-3 3"', 'range="-3 3" actuatorfrcrange="-23.7 23.7"')
    model = write("robots/arm.xml", limited)
    text = new_spec(model, model.with_name("arm.yaml")).text
    assert MOTORS.limited_to(23.7) == ["UnitreeGo1HipMotor", "UnitreeGo2HipMotor"]
    comments = " ".join(line.lstrip("# ").strip() for line in text.splitlines() if line.startswith("#"))
    assert (
        "decide: the file's effort limits are those of shipped motors (shoulder: UnitreeGo1HipMotor or "
        "UnitreeGo2HipMotor)" in comments
    )
    assert "motors" not in yaml.safe_load(text)  # proposed, not written


def test_new_names_no_motor_where_no_effort_limit_matches(write: Write) -> None:
    model: Path = write("robots/arm.xml", BARE)
    assert "shipped motors" not in new_spec(model, model.with_name("arm.yaml")).text
