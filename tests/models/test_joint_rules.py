"""Joint rules: MJCF values win where MuJoCo's default resolution says the file sets them."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.errors import SpecError
from assembler.models.provenance import Provenance
from tests.conftest import TWO_LINK_MJCF

Write = Callable[[str, str], Path]

WITHOUT_ELBOW_CLASS = TWO_LINK_MJCF.replace('range="-2 2" class="arm"', 'range="-2 2"')
WITHOUT_CLASSES = WITHOUT_ELBOW_CLASS.replace(' childclass="wrist"', "")


def _robot(write: Write, spec_body: str, mjcf: str = TWO_LINK_MJCF) -> assembler.RobotModel:
    write("r/twolink.xml", mjcf)
    spec = write("r/robot.yaml", "name: Rules\nmjcf: twolink.xml\n" + spec_body)
    (cls,) = assembler.register_specs(spec)
    return cls(idn=0)


def _compiled(robot: assembler.RobotModel, joint: str, attribute: str) -> float:
    value = getattr(robot.get_model().joint(robot.naming_prefix + joint), attribute)
    return float(value[0])


def test_rules_fill_only_what_the_file_leaves_unset(write: Write) -> None:
    robot = _robot(write, "")
    # shoulder: damping 3 and armature 2 come from childclass 'wrist' nested in 'arm'.
    assert _compiled(robot, "shoulder", "damping") == 3.0
    assert _compiled(robot, "shoulder", "armature") == 2.0
    assert _compiled(robot, "shoulder", "frictionloss") == pytest.approx(0.1)
    # elbow: explicit class 'arm' gives damping 3 but no armature -> rule 5.0/(1+1).
    assert _compiled(robot, "elbow", "damping") == 3.0
    assert _compiled(robot, "elbow", "armature") == pytest.approx(2.5)
    assert _compiled(robot, "elbow", "frictionloss") == pytest.approx(0.25)


def test_every_value_remembers_its_source(write: Write) -> None:
    robot = _robot(write, "")
    sources = {
        (joint, attribute): str(value.source)
        for joint, values in robot.joint_values.items()
        for attribute, value in values.items()
    }
    assert sources[("shoulder", "damping")] == "mjcf (class 'wrist')"
    assert sources[("shoulder", "frictionloss")] == "rule 0.1"
    assert sources[("elbow", "armature")] == "rule 5/(i+1)"
    assert sources[("elbow", "frictionloss")] == "mjcf (literal)"


def test_main_default_counts_as_set_by_the_file(write: Write) -> None:
    mjcf = TWO_LINK_MJCF.replace("<default>\n", '<default>\n    <joint damping="0.7"/>\n', 1)
    robot = _robot(write, "", mjcf)
    assert robot.joint_values["elbow"]["damping"].value == 3.0  # class beats main
    # shoulder's class chain (wrist <- arm) sets damping 3 too; main's 0.7 is only the fallback
    assert robot.joint_values["shoulder"]["damping"].source == Provenance("mjcf", how="main default")


def test_scalar_list_and_null_rules(write: Write) -> None:
    robot = _robot(
        write,
        "joint_defaults:\n  frictionloss: 0.5\n  armature: [0.3, 0.4]\n  damping: null\n",
        WITHOUT_CLASSES,
    )
    assert _compiled(robot, "shoulder", "frictionloss") == 0.5
    assert _compiled(robot, "shoulder", "armature") == pytest.approx(0.3)
    assert _compiled(robot, "elbow", "armature") == pytest.approx(0.4)
    assert _compiled(robot, "shoulder", "damping") == 0.0  # no rule: MuJoCo's default
    assert "damping" not in robot.joint_values["shoulder"]


def test_inverse_index_rule_with_another_scale(write: Write) -> None:
    robot = _robot(
        write,
        "joint_defaults:\n  armature: {inverse_index: 3.0}\n",
        TWO_LINK_MJCF.replace(' childclass="wrist"', ""),
    )
    assert _compiled(robot, "shoulder", "armature") == pytest.approx(3.0)
    assert _compiled(robot, "elbow", "armature") == pytest.approx(1.5)


def test_list_rule_of_the_wrong_length_points_at_the_spec(write: Write) -> None:
    with pytest.raises(SpecError, match=r"robot.yaml:4:12: joint_defaults.damping: expected 2 values"):
        _robot(write, "joint_defaults:\n  damping: [0.1, 0.2, 0.3]\n").check()


def test_glob_override_with_and_without_force(write: Write) -> None:
    robot = _robot(
        write,
        "joints:\n"
        "  - match: '*'\n    frictionloss: 0.05\n    force: false\n"
        "  - match: 'elb?w'\n    stiffness: 2.0\n",
        WITHOUT_CLASSES,
    )
    # elbow's frictionloss is written in the file: force: false keeps it
    assert _compiled(robot, "elbow", "frictionloss") == pytest.approx(0.25)
    # shoulder's came from the rule: replaced
    assert _compiled(robot, "shoulder", "frictionloss") == pytest.approx(0.05)
    assert _compiled(robot, "elbow", "stiffness") == 2.0
    assert robot.joint_values["elbow"]["stiffness"].source == Provenance("override", index=1)


def test_childclass_reaches_joints_in_descendant_bodies(write: Write) -> None:
    robot = _robot(write, "", WITHOUT_ELBOW_CLASS)
    # elbow sits in link2, below link1's childclass 'wrist' (nested in 'arm'), as MuJoCo resolves
    assert robot.joint_values["elbow"]["damping"].source == Provenance(
        "mjcf", how="class", class_name="wrist"
    )
    assert _compiled(robot, "elbow", "armature") == 2.0


def test_override_matching_no_joint_lists_the_joints(write: Write) -> None:
    with pytest.raises(SpecError) as caught:
        _robot(write, "joints:\n  - match: wrist\n    damping: 1\n").check()
    assert str(caught.value).endswith(
        "r/robot.yaml:4:12: joints[0].match: no joint matches 'wrist'. Joints: shoulder, elbow"
    )
