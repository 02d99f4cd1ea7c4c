"""The command line: each command's output and exit code, errors as lines without tracebacks."""

from __future__ import annotations

import argparse
import json
from collections.abc import Iterator
from pathlib import Path

import mujoco
import pytest

from assembler.cli import build_parser, main
from assembler.errors import summarize_names
from assembler.files.paths import shipped_specs_dir
from assembler.registry.lookup import REGISTRIES


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_list_shows_robots_with_morphology_and_dof(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "list")
    assert code == 0
    rows = {line.split()[0]: line.split() for line in out.splitlines()[1:]}
    assert rows["Sparrow7"][1:3] == ["manipulator", "7"]
    assert rows["Finch6"][1:3] == ["manipulator", "6"]


def test_validate_shipped_specs_exits_zero(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "validate", str(shipped_specs_dir()))
    assert code == 0
    assert all(line.startswith("note: ") for line in err.splitlines())  # robosuite may be absent
    assert "Sparrow7" in out


def test_validate_reports_every_problem_as_file_line_col(capsys: pytest.CaptureFixture[str], write) -> None:  # type: ignore[no-untyped-def]
    folder = write("specs/a.yaml", "name: A\nmjcf: a.xml\ndampng: 1\n").parent
    write("specs/b.yaml", "name: B\n")
    code, out, err = run(capsys, "validate", str(folder))
    assert code == 1 and out == ""
    lines = err.splitlines()
    assert len(lines) == 2
    assert (
        "a.yaml:3:1: dampng: unknown key 'dampng'. Valid keys here: actuators, add_free_joint, arm_type, balance_inertia, base_xpos_offset,"
        in lines[0]
    )
    assert lines[0].endswith(", remove_free_joint, robosuite, top_offset, urdf")
    assert lines[1].endswith("b.yaml:1:1: give exactly one of mjcf and urdf (the model file), got neither")
    assert "Traceback" not in err


def test_validate_checks_specs_against_their_mjcf(capsys: pytest.CaptureFixture[str], two_link: Path) -> None:
    two_link.write_text("name: TwoLink\nmjcf: twolink.xml\njoints:\n  - {match: joint9, damping: 1}\n")
    code, _, err = run(capsys, "validate", str(two_link))
    assert code == 1
    assert err.strip().endswith(
        "twolink.yaml:4:13: joints[0].match: no joint matches 'joint9'. Joints: shoulder, elbow"
    )


def test_build_writes_a_compiled_standalone_model(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out = tmp_path / "robot.xml"
    code, _, err = run(capsys, "build", "Sparrow7", "--idn", "2", "-o", str(out))
    assert code == 0 and "wrote" in err
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.joint(0).name == "robot2_joint1" and model.nkey == 1


def test_build_with_bundle(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    code, _, _ = run(capsys, "build", "Finch6", "--bundle", str(tmp_path / "b"))
    assert code == 0
    assert mujoco.MjModel.from_xml_path(str(tmp_path / "b" / "Finch6.xml")).nu == 6 + 3  # arm + TriHand


def test_build_accepts_a_spec_file_and_user_spec_folders(
    capsys: pytest.CaptureFixture[str], two_link: Path
) -> None:
    code, out, _ = run(capsys, "build", str(two_link))
    assert code == 0 and out.startswith("<mujoco")
    code, out, _ = run(capsys, "--specs", str(two_link.parent), "build", "TwoLink")
    assert code == 0 and "robot0_shoulder" in out


def test_unknown_robot_is_one_line_with_a_suggestion(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "build", "Sparow7")
    assert (code, out) == (1, "")
    assert err == "unknown robot 'Sparow7'. Did you mean 'Sparrow7'?\n"
    assert len(err.splitlines()) == 1


def test_inspect_shows_each_value_and_its_source(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "inspect", "Sparrow7")
    assert code == 0
    rows = {line.split()[0]: line for line in out.splitlines() if line.startswith("robot0_")}
    assert rows["robot0_joint1"].split() == [
        "robot0_joint1",
        "0.1",
        "rule",
        "0.1",
        "0.1",
        "rule",
        "0.1",
        "5",
        "rule",
        "5/(i+1)",
    ]
    assert "0.01  mjcf (class 'wrist')" in rows["robot0_joint7"]
    assert "0.714286  rule 5/(i+1)" in rows["robot0_joint7"]


def test_inspect_json(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "inspect", "Finch6", "--format", "json")
    table = json.loads(out)["joints"]
    assert table["robot0_joint6"]["armature"] == {
        "value": pytest.approx(5 / 6),
        "source": "rule 5/(i+1)",
        "origin": "rule",
    }


def test_schema_is_json_schema_with_every_field_documented(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "schema")
    schema = json.loads(out)
    assert code == 0 and schema["$schema"].startswith("https://json-schema.org/")
    assert [ref["$ref"] for ref in schema["anyOf"]] == [
        "#/$defs/RobotSpec",
        "#/$defs/BaseSpec",
        "#/$defs/GripperSpec",
        "#/$defs/MotorSpec",
        "#/$defs/SceneSpec",
        "#/$defs/ExperimentSpec",
    ]
    robot = schema["$defs"]["RobotSpec"]
    assert robot["additionalProperties"] is False and robot["else"]["required"] == ["name"]
    assert robot["else"]["oneOf"] == [{"required": ["mjcf"]}, {"required": ["urdf"]}]
    assert robot["if"] == {"required": ["extends"]} and robot["then"]["required"] == ["name"]  # inherits mjcf
    undocumented = [
        f"{name}.{field}"
        for name, definition in schema["$defs"].items()
        for field, body in definition.get("properties", {}).items()
        if not body.get("description")
    ]
    assert undocumented == []


def test_build_with_base_and_gripper_choices(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out = tmp_path / "out.xml"
    code, _, _ = run(
        capsys, "build", "TwinTorso", "--gripper", "right=TriHand", "--gripper", "left=none", "-o", str(out)
    )
    assert code == 0
    model = mujoco.MjModel.from_xml_path(str(out))
    bodies = {model.body(i).name for i in range(model.nbody)}
    assert "gripper0_right_tri_hand" in bodies
    assert not any(name.startswith("gripper0_left_") for name in bodies)


def test_build_arm_only(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out = tmp_path / "arm.xml"
    assert run(capsys, "build", "Sparrow7", "--no-base", "--no-grippers", "-o", str(out))[0] == 0
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.nu == 7 and model.nbody == 1 + 9  # world + base, link1..7, right_hand


def test_bad_gripper_choice_is_one_line(capsys: pytest.CaptureFixture[str]) -> None:
    code, _, err = run(capsys, "build", "Sparrow7", "--gripper", "TriHand")
    assert code == 1
    assert err == "--gripper expects ARM=NAME (e.g. right=PincerGripper or left=none), got 'TriHand'\n"


def test_list_bases_and_grippers(capsys: pytest.CaptureFixture[str]) -> None:
    _, out, _ = run(capsys, "list", "bases")
    listed = {line.split()[0]: line.split()[1] for line in out.splitlines()[1:]}
    assert {
        name: kind
        for name, kind in listed.items()
        if name in {"Pedestal", "QuadrupedBase", "RoverBase", "SiteOnlyBase"}
    } == {
        "Pedestal": "mount",
        "QuadrupedBase": "legged",
        "RoverBase": "mobile",
        "SiteOnlyBase": "null",
    }
    _, out, _ = run(capsys, "list", "grippers")
    assert "PincerGripper" in out and "TriHand" in out


def test_scene_places_robots_with_unique_names(capsys: pytest.CaptureFixture[str], tmp_path: Path) -> None:
    out = tmp_path / "scene.xml"
    scene = Path(__file__).parents[2] / "scenes" / "two_arms.yaml"
    code, _, err = run(capsys, "scene", str(scene), "-o", str(out))
    assert code == 0 and "Sparrow70, Finch61" in err
    model = mujoco.MjModel.from_xml_path(str(out))
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    assert data.body("robot0_base").xpos[0] == pytest.approx(-0.6)
    assert data.body("robot1_base").xpos[0] == pytest.approx(0.6)
    assert data.body("mobilebase1_base").xpos[2] == pytest.approx(0.0, abs=1e-9)  # the rover on the floor
    assert model.body("robot1_manipulator_mount").parentid[0] == model.body("mobilebase1_support").id


def _options(parser: argparse.ArgumentParser, command: str) -> Iterator[tuple[str, argparse.Action]]:
    for action in parser._actions:
        if isinstance(action, argparse._SubParsersAction):
            for name, subparser in action.choices.items():
                yield from _options(subparser, name)
        elif not isinstance(action, argparse._HelpAction):
            yield command, action


def test_every_option_of_every_command_has_help_text() -> None:
    missing = [
        (command, action.dest) for command, action in _options(build_parser(), "assembler") if not action.help
    ]
    assert missing == []


@pytest.mark.parametrize("where", ["before", "after"])
def test_specs_and_allow_path_work_before_or_after_the_command(
    where: str, two_link: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    options = ["--specs", str(two_link.parent), "--allow-path", str(two_link.parent)]
    argv = [*options, "inspect", "TwoLink"] if where == "before" else ["inspect", "TwoLink", *options]
    code, out, _ = run(capsys, *argv)
    assert code == 0 and "robot0_shoulder" in out


def test_validate_help_offers_only_the_formats_it_accepts(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit):
        main(["validate", "--help"])
    text = " ".join(capsys.readouterr().out.split())
    assert "--format {text,github}" in text and "json" not in text


def test_validate_with_no_path_validates_the_specs_folders(
    capsys: pytest.CaptureFixture[str], two_link: Path
) -> None:
    code, out, err = run(capsys, "--specs", str(two_link.parent), "validate", "--compile")
    assert (code, out, err) == (0, "1 spec(s) validated and compiled: TwoLink\n", "")


def test_validate_counts_the_specs_it_could_not_check_against_their_mjcf(
    capsys: pytest.CaptureFixture[str], two_link: Path
) -> None:
    (two_link.parent / "ghost.yaml").write_text(
        "name: Ghost\nmjcf: package://no_such_package_here/robot.xml\n"
    )
    code, out, err = run(capsys, "validate", str(two_link.parent), "--compile")
    assert (code, err) == (0, "")
    assert out.splitlines() == [
        "1 spec(s) validated and compiled: TwoLink",
        "1 spec(s) valid but not checked against their model file nor compiled: Ghost",
        "    because: Python package 'no_such_package_here' is not installed; install it",
    ]


def test_validate_counts_scene_and_experiment_files(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(shipped_specs_dir().parent)
    code, out, _ = run(capsys, "validate", "scenes", "experiments")
    assert (code, out) == (
        0,
        "2 scene and experiment file(s) valid: scenes/two_arms.yaml, experiments/soft_pair.yaml\n",
    )


@pytest.mark.parametrize(
    ("file", "spec", "kind"),
    [
        pytest.param("arm.yaml", "name: Arm\nextends: Zzzzzz\n", "robot", id="robot"),
        pytest.param("hand.yaml", "name: Hand\nkind: gripper\nextends: Zzzzzz\n", "gripper", id="gripper"),
        pytest.param(
            "cart.yaml", "name: Cart\nkind: base\ntype: mobile\nextends: Zzzzzz\n", "base", id="base"
        ),
    ],
)
def test_extends_an_unknown_name_with_no_close_match_lists_names_of_its_kind_only(
    capsys: pytest.CaptureFixture[str],
    write,
    file: str,
    spec: str,
    kind: str,  # type: ignore[no-untyped-def]
) -> None:
    path = write(f"mine/{file}", spec)
    code, _, err = run(capsys, "validate", str(path))
    line = spec.count("\n")
    known = summarize_names(sorted(REGISTRIES[kind]), limit=20)
    assert (code, err) == (
        1,
        f"{path}:{line}:10: extends: unknown {kind} spec 'Zzzzzz'. Known {kind}s: {known}\n",
    )


def test_list_sorts_by_name_and_shows_shipped_specs_short_from_anywhere(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.chdir(tmp_path)  # outside the checkout, as after a wheel install
    for what in ("robots", "bases", "grippers"):
        code, out, _ = run(capsys, "list", what)
        rows = [line.split() for line in out.splitlines()[1:]]
        names = [row[0] for row in rows]
        assert code == 0 and names == sorted(names, key=str.casefold)
        assert all(row[-2].startswith("specs/") and row[-2:][1] == "(shipped)" for row in rows)
        if what == "robots":
            assert ["Sparrow7", "manipulator", "7", "specs/sparrow7.yaml", "(shipped)"] in rows
