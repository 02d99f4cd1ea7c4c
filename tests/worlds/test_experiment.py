"""Experiment files: robots with overrides, bases and grippers; one robot alone, several in a scene."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco
import pytest

import assembler
from assembler.cli import main
from assembler.errors import SpecError
from assembler.registry.lookup import REGISTERED_ROBOTS

TWO_ROBOTS = """\
kind: experiment
name: soft_pair
robots:
  - robot: Sparrow7
    pos: [-0.6, 0.0, 0.0]
    overrides:
      joint_defaults.damping: 0.2
      init_qpos[3]: -2.0
  - robot: Finch6
    base: RoverBase
    grippers: {right: PincerGripper}
    pos: [0.6, 0.0, 0.0]
    ori: [0.0, 0.0, 3.14159265]
    overrides: {joint_defaults.frictionloss: 0.05}
"""

Write = Callable[[str, str], Path]


def test_two_robots_become_a_scene_with_each_robots_overrides(write: Write) -> None:
    before = dict(REGISTERED_ROBOTS)
    experiment = assembler.load_experiment(write("exp.yaml", TWO_ROBOTS))
    assert experiment.scene is not None
    assert [robot.name for robot in experiment.robots] == ["Sparrow70", "Finch61"]
    model = experiment.get_model()
    assert model.geom("scene_floor").type == mujoco.mjtGeom.mjGEOM_PLANE
    assert model.joint("robot0_joint2").damping[0] == pytest.approx(0.2)
    assert model.joint("robot1_joint2").damping[0] == pytest.approx(0.1)  # not Sparrow7's override
    assert model.joint("robot1_joint2").frictionloss == pytest.approx(0.05)
    assert model.joint("robot0_joint2").frictionloss == pytest.approx(0.1)
    assert model.key("home").qpos[model.jnt_qposadr[model.joint("robot0_joint4").id]] == pytest.approx(-2.0)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert data.body("robot0_base").xpos[0] == pytest.approx(-0.6)
    assert data.body("robot1_base").xpos[0] == pytest.approx(0.6)
    assert before == REGISTERED_ROBOTS


def test_one_robot_is_built_alone_like_build_with_set(write: Write) -> None:
    path = write(
        "one.yaml",
        """\
        kind: experiment
        name: soft
        robots:
          - robot: Sparrow7
            idn: 3
            overrides: {joint_defaults.damping: 0.2}
        """,
    )
    experiment = assembler.load_experiment(path)
    assert experiment.scene is None
    built = assembler.assemble("Sparrow7", idn=3, overrides=["joint_defaults.damping=0.2"])
    assert experiment.get_xml() == built.get_xml()


def test_a_robot_spec_file_is_found_next_to_the_experiment(write: Write, two_link: Path) -> None:
    path = write(
        "robots/exp.yaml",
        "kind: experiment\nname: e\nrobots:\n  - robot: twolink.yaml\n    overrides:\n      init_qpos[1]: 0.25\n",
    )
    experiment = assembler.load_experiment(path)
    assert experiment.robots[0].spec.init_qpos == [0.5, 0.25]
    assert experiment.get_model().key("home").qpos[1] == pytest.approx(0.25)


def test_problems_point_at_the_experiment_file(write: Write) -> None:
    path = write(
        "bad.yaml",
        """\
        kind: experiment
        name: bad
        robots:
          - robot: Sparow7
          - robot: Finch6
            overrides:
              joint_defaults.dampin: 0.2
              init_qpos[9]: 1
          - robot: Finch6
            idn: 1
        """,
    )
    with pytest.raises(SpecError) as caught:
        assembler.load_experiment(path)
    lines = str(caught.value).replace(f"{path.parent}/", "").splitlines()
    assert lines[0].startswith(
        "bad.yaml:4:12: robots[0].robot: unknown robot 'Sparow7'. Did you mean 'Sparrow7'?"
    )
    assert lines[1:] == [
        "bad.yaml:7:7: robots[1].overrides.joint_defaults.dampin: unknown key 'dampin'. "
        "Did you mean 'damping'? Valid keys here: armature, damping, frictionloss",
        "bad.yaml:8:7: robots[1].overrides.init_qpos[9]: index 9 is out of range: "
        "init_qpos has 6 values (indexes 0 to 5)",
        "bad.yaml:10:10: robots[2].idn: idn 1 is already used by robots[1]; give each robot its own",
    ]


def test_the_file_itself_is_checked_by_the_schema(write: Write) -> None:
    path = write("e.yaml", "kind: experiment\nname: e\nrobots:\n  - robot: Sparrow7\n    overide: {}\n")
    with pytest.raises(
        SpecError, match=r"e.yaml:5:5: robots\[0\].overide: unknown key 'overide'. Did you mean 'overrides'\?"
    ):
        assembler.load_experiment(path)


def test_the_experiment_command_writes_the_compiled_model(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path
) -> None:
    target = tmp_path / "out.xml"
    code = main(["experiment", str(write("exp.yaml", TWO_ROBOTS)), "-o", str(target)])
    err = capsys.readouterr().err
    assert code == 0, err
    assert err.endswith(
        ": Sparrow70 (joint_defaults.damping=0.2, init_qpos[3]=-2.0), "
        "Finch61 (joint_defaults.frictionloss=0.05)\n"
    )
    model = mujoco.MjModel.from_xml_path(str(target))
    assert model.joint("robot0_joint2").damping[0] == pytest.approx(0.2) and model.nkey == 1


def test_a_failing_experiment_writes_nothing(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path
) -> None:
    target = tmp_path / "out.xml"
    path = write(
        "e.yaml",
        "kind: experiment\nname: e\nrobots:\n  - robot: Sparrow7\n    overrides: {top_offset: [1]}\n",
    )
    code = main(["experiment", str(path), "-o", str(target)])
    err = capsys.readouterr().err
    assert code == 1 and not target.exists()
    assert err.endswith("e.yaml:5:17: robots[0].overrides.top_offset: expected 3 values, got 1\n")
