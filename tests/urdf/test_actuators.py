"""Actuators declared in a spec (``actuators:``), on an MJCF robot: force semantics, provenance, errors."""

from __future__ import annotations

from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.errors import SpecError


def _robot(two_link: Path, extra: str) -> assembler.RobotModel:
    two_link.write_text(two_link.read_text() + extra)
    (cls,) = assembler.register_specs(two_link)
    robot = cls(idn=0)
    assert isinstance(robot, assembler.RobotModel)
    return robot


def test_a_declared_actuator_replaces_the_files_own(two_link: Path) -> None:
    robot = _robot(two_link, "actuators:\n  - {match: shoulder, kp: 10, dampratio: 1}\n")
    model = robot.get_model()
    assert [model.actuator(a).name for a in range(model.nu)] == ["robot0_act_elbow", "robot0_shoulder"]
    assert model.actuator("robot0_shoulder").gainprm[0] == 10
    assert [(r.name, r.source) for r in robot.actuator_table] == [
        ("act_elbow", "mjcf"),
        ("shoulder", "spec actuators[0]"),
    ]


def test_force_false_keeps_the_files_actuator(two_link: Path) -> None:
    robot = _robot(two_link, 'actuators:\n  - {match: "*", type: motor, gear: 2, force: false}\n')
    model = robot.get_model()
    assert [model.actuator(a).name for a in range(model.nu)] == ["robot0_act_shoulder", "robot0_act_elbow"]


def test_a_motor_takes_the_joints_effort_over_its_gear_as_control_range(two_link: Path) -> None:
    text = two_link.read_text().replace('range="-3 3"/>', 'range="-3 3" actuatorfrcrange="-8 8"/>')
    two_link.parent.joinpath("twolink.xml").write_text(
        two_link.parent.joinpath("twolink.xml")
        .read_text()
        .replace(
            '<joint name="shoulder" axis="0 0 1" range="-3 3"/>',
            '<joint name="shoulder" axis="0 0 1" range="-3 3" actuatorfrcrange="-8 8"/>',
        )
    )
    two_link.write_text(text)
    robot = _robot(
        two_link, "actuators:\n  - {match: shoulder, type: motor, gear: 2, name: '{joint}_motor'}\n"
    )
    actuator = robot.get_model().actuator("robot0_shoulder_motor")
    assert list(actuator.ctrlrange) == [-4.0, 4.0] and list(actuator.forcerange) == [-8.0, 8.0]


INVALID = [
    ("{match: shoulder, type: velocity, kp: 3}", "5:5: actuators[0]: a velocity actuator takes kv, not kp"),
    ("{match: shoulder}", "5:5: actuators[0]: a position actuator needs kp"),
    ("{match: shoulder, kp: 1, kv: 1, dampratio: 1}", "5:5: actuators[0]: give kv or dampratio, not both"),
    ("{match: shoulder, type: general}", "5:5: actuators[0]: a general actuator needs gainprm"),
    ("{match: wrist, kp: 1}", "5:13: actuators[0].match: no joint matches 'wrist'. Joints: shoulder, elbow"),
    (
        "{match: shoulder, kp: 1, name: act_elbow}",
        "5:36: actuators[0].name: an actuator named 'act_elbow' already exists; give the entry another name",
    ),
]


@pytest.mark.parametrize(("entry", "expected"), INVALID)
def test_invalid_actuator_entries_give_one_exact_line(two_link: Path, entry: str, expected: str) -> None:
    with pytest.raises(SpecError) as caught:
        _robot(two_link, f"actuators:\n  - {entry}\n").check()  # parts read their file when first used
    (line,) = str(caught.value).splitlines()
    assert line.endswith(expected)


def test_inspect_shows_each_actuator_value_and_its_source(
    two_link: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    two_link.write_text(two_link.read_text() + "actuators:\n  - {match: elbow, kp: 20, kv: 2}\n")
    assert main(["inspect", str(two_link)]) == 0
    out = capsys.readouterr().out
    assert "robot0_act_shoulder  robot0_shoulder  file      mjcf" in out
    assert (
        "robot0_elbow         robot0_elbow     position  spec actuators[0]  kp 20 (spec); kv 2 (spec); "
        "ctrlrange [-2, 2] (joint range); forcerange unlimited (joint effort limit)"
    ) in out
