"""Overrides: typed by the schema, errors that list the valid keys, and a registry left alone."""

from __future__ import annotations

from pathlib import Path

import mujoco
import pytest

import assembler
from assembler.cli import main
from assembler.errors import AssemblerError, SpecError
from assembler.registry.lookup import REGISTERED_ROBOTS


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_text_values_are_typed_by_the_schema() -> None:
    robot = assembler.create_robot(
        "Sparrow7", idn=0, overrides=["joint_defaults.damping=0.2", "init_qpos[3]=-2.0"]
    )
    assert robot.spec.joint_defaults.damping == 0.2 and isinstance(robot.spec.joint_defaults.damping, float)
    assert robot.spec.init_qpos == [0.0, -0.785, 0.0, -2.0, 0.0, 1.571, 0.785]
    model = robot.get_model()
    assert model.joint("robot0_joint1").damping[0] == pytest.approx(0.2)
    assert model.joint("robot0_joint6").damping[0] == pytest.approx(0.01)  # the MJCF's own value stays
    assert model.key("home").qpos[3] == pytest.approx(-2.0)


def test_a_mapping_of_dotted_keys_and_flow_values_work_too() -> None:
    robot = assembler.create_robot(
        "Finch6",
        idn=1,
        overrides={
            "joint_defaults.armature": {"inverse_index": 3.0},
            "joints": [{"match": "joint[56]", "damping": 4}],
        },
    )
    model = robot.get_model()
    assert model.joint("robot1_joint2").armature == pytest.approx(1.5)
    assert model.joint("robot1_joint5").damping[0] == pytest.approx(4.0)


def test_assemble_takes_overrides_for_the_robot() -> None:
    robot = assembler.assemble("Sparrow7", idn=0, overrides={"joint_defaults.frictionloss": 0.3})
    model = robot.get_model()
    assert model.joint("robot0_joint1").frictionloss == pytest.approx(0.3)
    assert model.joint("gripper0_right_finger_joint1").frictionloss != pytest.approx(0.3)


def test_the_registry_is_unchanged_by_an_override() -> None:
    before = dict(REGISTERED_ROBOTS)
    original_spec = REGISTERED_ROBOTS["Sparrow7"].spec
    robot = assembler.create_robot("Sparrow7", idn=0, overrides={"joint_defaults.damping": 0.2})
    cls = type(robot)
    assert before == REGISTERED_ROBOTS and REGISTERED_ROBOTS["Sparrow7"] is before["Sparrow7"]
    assert cls is not before["Sparrow7"] and issubclass(cls, before["Sparrow7"])
    assert cls.__name__ == "Sparrow7" and robot.name == "Sparrow70"
    assert REGISTERED_ROBOTS["Sparrow7"].spec is original_spec
    assert original_spec.joint_defaults.damping == 0.1
    assert assembler.create_robot("Sparrow7", idn=0).spec.joint_defaults.damping == 0.1


def test_the_spec_shows_the_overrides_so_a_cache_keyed_on_it_sees_them() -> None:
    plain = assembler.create_robot("Sparrow7", idn=0)
    changed = assembler.create_robot("Sparrow7", idn=0, overrides={"joint_defaults.damping": 0.2})
    assert '"damping":0.2' in type(changed).spec.model_dump_json()
    assert type(plain).spec.model_dump_json() != type(changed).spec.model_dump_json()


def test_an_override_applies_after_extends_is_resolved(write) -> None:  # type: ignore[no-untyped-def]
    spec = write("soft.yaml", "name: SoftSparrow\nextends: Sparrow7\njoint_defaults: {damping: 0.5}\n")
    (cls,) = assembler.register_specs(spec)
    robot = assembler.create_robot("SoftSparrow", idn=0, overrides=["joint_defaults.frictionloss=0.02"])
    assert robot.spec.joint_defaults.damping == 0.5  # from the child spec
    assert robot.spec.joint_defaults.frictionloss == 0.02  # from the override
    assert robot.spec.init_qpos == cls.spec.init_qpos  # from the parent


@pytest.mark.parametrize(
    ("override", "message"),
    [
        (
            "joint_defaults.dampin=0.2",
            "override joint_defaults.dampin: unknown key 'dampin'. Did you mean 'damping'? "
            "Valid keys here: armature, damping, frictionloss",
        ),
        (
            "init_qpos[7]=0",
            "override init_qpos[7]: index 7 is out of range: init_qpos has 7 values (indexes 0 to 6)",
        ),
        (
            "joint_defaults.damping=abc",
            "override joint_defaults.damping: expected a non-negative number, a list of them (one per joint), "
            "a mapping 'inverse_index: <scale>' or null, got 'abc'",
        ),
        (
            "joint_defaults.damping[2]=0.1",
            "override joint_defaults.damping[2]: joint_defaults.damping is 0.1, not a list; "
            "set the whole list: joint_defaults.damping=[...]",
        ),
        (
            "joints[0].damping=1",
            "override joints[0].damping: joints is not set; set the whole list: joints=[...]",
        ),
        (
            "init_qpos.x=1",
            "override init_qpos.x: init_qpos is a list; pick an item by index, e.g. init_qpos[0]",
        ),
        ("top_offset=[1, 2]", "override top_offset: expected 3 values, got 2"),
        (
            "name=Other",
            "override name: 'name' chooses the class and cannot be overridden; write a spec with extends:",
        ),
        ("init_qpos=[1, 2]", "override init_qpos: expected 7 values (one per joint: joint1, joint2, joint3"),
        ("mjcf=missing.xml", "override mjcf: MJCF file not found: missing.xml"),
        ("damping", "override: expected PATH=VALUE (e.g. joint_defaults.damping=0.2), got 'damping'"),
    ],
)
def test_override_mistakes_are_one_line_naming_the_override(override: str, message: str) -> None:
    with pytest.raises(AssemblerError) as caught:
        assembler.create_robot("Sparrow7", idn=0, overrides=[override]).check()
    assert str(caught.value).startswith(message)
    assert len(caught.value.problems) == 1


def test_a_problem_an_override_causes_elsewhere_says_so() -> None:
    with pytest.raises(
        SpecError, match=r"default_grippers names arm 'left'.*\(with the overrides default_grippers.left\)"
    ):
        assembler.create_robot("Sparrow7", idn=0, overrides={"default_grippers.left": "TriHand"}).check()


def test_build_set_flags_write_the_overridden_model(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    target = tmp_path / "soft.xml"
    code, _, err = run(
        capsys,
        "build",
        "Sparrow7",
        "--set",
        "joint_defaults.damping=0.2",
        "--set",
        "init_qpos[3]=-2.0",
        "-o",
        str(target),
    )
    assert code == 0, err
    model = mujoco.MjModel.from_xml_path(str(target))
    assert model.joint("robot0_joint2").damping[0] == pytest.approx(0.2)
    assert model.key("home").qpos[3] == pytest.approx(-2.0)


def test_build_with_a_bad_set_flag_is_one_line_and_writes_nothing(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    target = tmp_path / "soft.xml"
    code, out, err = run(capsys, "build", "Sparrow7", "--set", "joint_defaults.dampin=0.2", "-o", str(target))
    assert code == 1 and out == "" and not target.exists()
    assert err == (
        "--set joint_defaults.dampin: unknown key 'dampin'. Did you mean 'damping'? "
        "Valid keys here: armature, damping, frictionloss\n"
    )


def test_inspect_shows_the_overrides_and_the_values_they_give(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, _ = run(capsys, "inspect", "Finch6", "--set", "joint_defaults.damping=0.2")
    assert code == 0
    assert "overrides: joint_defaults.damping=0.2" in out
    row = next(line for line in out.splitlines() if line.startswith("robot0_joint1 "))
    assert "0.2  rule 0.2" in row


def test_an_mjcf_override_outside_the_allowed_folders_names_the_override(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    assert main(["build", "Sparrow7", "--set", "mjcf=/etc/passwd", "-o", str(tmp_path / "x.xml")]) == 1
    assert capsys.readouterr().err.startswith(
        "--set mjcf: /etc/passwd is outside the folders a spec may read"
    )
    assert not (tmp_path / "x.xml").exists()


def _nested(depth: int) -> object:
    value: object = 0.1
    for _ in range(depth):
        value = [value]
    return value


@pytest.mark.parametrize("depth", [65, 3000])
def test_an_override_value_nested_deeper_than_a_spec_file_may_is_one_line(depth: int) -> None:
    """Found by the hostile-input battery (as --set; here its Python form): a RecursionError before."""
    with pytest.raises(SpecError) as caught:
        assembler.assemble("Sparrow7", overrides={"joint_defaults.damping": _nested(depth)}).get_model()
    assert (
        str(caught.value) == "override joint_defaults.damping: nesting depth exceeds the limit of 64 levels"
    )
