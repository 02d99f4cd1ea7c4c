"""``assembler diff``: spec fields and compiled-model values that changed, as text, Markdown and JSON."""

from __future__ import annotations

import json
import subprocess
from collections.abc import Callable
from pathlib import Path

import pytest

from assembler.cli import main
from assembler.registry.lookup import REGISTERED_ROBOTS
from tests.conftest import TWO_LINK_MJCF, TWO_LINK_SPEC

THREE_LINK_MJCF = TWO_LINK_MJCF.replace(
    '<body name="right_hand" pos="0.3 0 0"/>',
    """<body name="link3" pos="0.3 0 0">
            <joint name="wrist" axis="0 0 1" range="-1 1"/>
            <geom name="link3_col" type="sphere" size="0.03" mass="0.2"/>
            <body name="right_hand" pos="0.05 0 0"/>
          </body>""",
).replace('size="0.03" mass="1"/>', 'size="0.03" mass="2"/>')
"""The two-link robot with a third link (body, joint) and link1's mass doubled."""

Write = Callable[[str, str], Path]


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def rows(text: str) -> list[list[str]]:
    """The output's lines as whitespace-separated words (the columns are aligned with spaces)."""
    return [line.split() for line in text.splitlines()]


@pytest.fixture
def pair(write: Write) -> tuple[Path, Path]:
    """Two versions of one robot: the second overrides elbow damping and changes the frictionloss rule."""
    write("robots/twolink.xml", TWO_LINK_MJCF)
    before = write("robots/twolink.yaml", TWO_LINK_SPEC)
    after = write(
        "robots/twolink_b.yaml",
        TWO_LINK_SPEC + "joint_defaults: {frictionloss: 0.2}\njoints:\n  - {match: elbow, damping: 0.5}\n",
    )
    return before, after


def test_changed_rule_and_override_show_as_spec_fields_and_joint_values(
    capsys: pytest.CaptureFixture[str], pair: tuple[Path, Path]
) -> None:
    code, out, err = run(capsys, "diff", str(pair[0]), str(pair[1]))
    assert (code, err) == (0, "")
    lines = rows(out)
    assert ["joint_defaults.frictionloss", "0.1", "->", "0.2"] in lines
    assert [
        "joints[0]",
        "-",
        "->",
        '{"match":',
        '"elbow",',
        '"frictionloss":',
        "null,",
        '"damping":',
        "0.5,",
        '"armature":',
        "null,",
        '"stiffness":',
        "null,",
        '"force":',
        "true}",
    ] in lines
    # the rule reaches only the joint whose MJCF sets no frictionloss; the elbow sets 0.25 itself
    assert ["joint", "robot0_shoulder", "frictionloss", "0.1", "->", "0.2"] in lines
    assert ["joint", "robot0_elbow", "damping", "3", "->", "0.5"] in lines
    assert not any(line[:2] == ["joint", "robot0_elbow"] and "frictionloss" in line for line in lines)


def test_added_link_and_changed_mass_show_in_the_model(
    capsys: pytest.CaptureFixture[str], write: Write, pair: tuple[Path, Path]
) -> None:
    write("robots/threelink.xml", THREE_LINK_MJCF)
    after = write(
        "robots/threelink.yaml",
        TWO_LINK_SPEC.replace("twolink.xml", "threelink.xml").replace("[0.5, -0.5]", "[0.5, -0.5, 0.1]"),
    )
    code, out, _ = run(capsys, "diff", str(pair[0]), str(after))
    lines = rows(out)
    assert code == 0
    assert "init_qpos  [0.5, -0.5] -> [0.5, -0.5, 0.1]" in out
    assert "+ 1 body added: robot0_link3" in out
    assert "+ 1 joint added: robot0_wrist" in out
    # the body's mass also counts its visual geom's (density times volume: 1.03051)
    assert ["body", "robot0_link1", "mass", "2.03051", "->", "3.03051"] in lines
    assert "removed" not in out


def test_markdown_has_a_table_per_section(
    capsys: pytest.CaptureFixture[str], pair: tuple[Path, Path]
) -> None:
    code, out, _ = run(capsys, "diff", str(pair[0]), str(pair[1]), "--format", "markdown")
    assert code == 0
    assert out.splitlines()[0] == f"### `{pair[0]}` → `{pair[1]}`"
    assert "| field | before | after |" in out
    assert "| `joint_defaults.frictionloss` | 0.1 | 0.2 |" in out
    assert "| element | name | property | before | after |" in out
    assert "| joint | `robot0_elbow` | damping | 3 | 0.5 |" in out


def test_json_keeps_values_unrounded(capsys: pytest.CaptureFixture[str], pair: tuple[Path, Path]) -> None:
    code, out, _ = run(capsys, "diff", str(pair[0]), str(pair[1]), "--format", "json")
    document = json.loads(out)
    assert code == 0 and document["identical"] is False
    assert {
        "path": "joint_defaults.frictionloss",
        "kind": "changed",
        "before": 0.1,
        "after": 0.2,
    } in document["spec"]
    assert {
        "element": "joint",
        "name": "robot0_elbow",
        "property": "damping",
        "before": 3.0,
        "after": 0.5,
    } in (document["model"]["changed"])
    assert document["model"]["added"] == {"body": [], "joint": [], "actuator": []}


def test_identical_specs_say_so_and_exit_code_is_opt_in(
    capsys: pytest.CaptureFixture[str], pair: tuple[Path, Path]
) -> None:
    code, out, _ = run(capsys, "diff", str(pair[0]), str(pair[0]), "--exit-code")
    assert (code, out.splitlines()[-1]) == (0, "no differences")
    assert run(capsys, "diff", str(pair[0]), str(pair[1]))[0] == 0
    assert run(capsys, "diff", str(pair[0]), str(pair[1]), "--exit-code")[0] == 1


def test_two_versions_of_one_robot_are_not_registered(
    capsys: pytest.CaptureFixture[str], pair: tuple[Path, Path]
) -> None:
    run(capsys, "diff", str(pair[0]), str(pair[1]))
    assert "TwoLink" not in REGISTERED_ROBOTS


def test_registered_name_and_its_spec_file_are_identical(capsys: pytest.CaptureFixture[str]) -> None:
    from assembler.files.paths import shipped_specs_dir

    code, out, _ = run(capsys, "diff", "Sparrow7", str(shipped_specs_dir() / "sparrow7.yaml"))
    assert (code, out.splitlines()[-1]) == (0, "no differences")


def test_unknown_side_is_one_line_with_a_suggestion(capsys: pytest.CaptureFixture[str]) -> None:
    code, out, err = run(capsys, "diff", "Sparow7", "Sparrow7")
    assert (code, out) == (1, "")
    assert err.startswith(
        "'Sparow7' is neither a spec file, FILE@REVISION nor a registered name. Did you mean 'Sparrow7'?"
    )
    assert len(err.splitlines()) == 1


def git(repository: Path, *arguments: str) -> None:
    subprocess.run(
        ["git", "-c", "user.name=test", "-c", "user.email=test@example.com", *arguments],
        cwd=repository,
        check=True,
        capture_output=True,
    )


def test_spec_at_a_git_revision_reads_its_file_parent_at_that_revision(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path
) -> None:
    write("robots/twolink.xml", TWO_LINK_MJCF)
    parent = write("robots/twolink.yaml", TWO_LINK_SPEC)
    child = write("robots/soft.yaml", "name: TwoLinkSoft\nextends: twolink.yaml\n")
    git(tmp_path, "init", "-q")
    git(tmp_path, "add", ".")
    git(tmp_path, "commit", "-q", "-m", "first")
    parent.write_text(TWO_LINK_SPEC + "joint_defaults: {armature: 0.5}\n")  # changed in the working tree only

    code, out, err = run(capsys, "diff", f"{child}@HEAD", str(child))
    assert (code, err) == (0, "")
    lines = rows(out)
    assert out.splitlines()[0] == f"--- {child}@HEAD"
    assert ["joint_defaults.armature", '{"inverse_index":', "5.0}", "->", "0.5"] in lines
    assert ["joint", "robot0_elbow", "armature", "2.5", "->", "0.5"] in lines  # 5 / (i + 1)
    assert "extends" not in out  # the child's own extends: line did not change


@pytest.fixture
def spec_in_repository(write: Write, tmp_path: Path) -> Path:
    """The two-link spec in a git repository with no commits."""
    write("robots/twolink.xml", TWO_LINK_MJCF)
    spec = write("robots/twolink.yaml", TWO_LINK_SPEC)
    git(tmp_path, "init", "-q")
    return spec


def test_unknown_revision_is_one_line(capsys: pytest.CaptureFixture[str], spec_in_repository: Path) -> None:
    spec = spec_in_repository
    code, out, err = run(capsys, "diff", f"{spec}@nosuchrev", str(spec))
    assert (code, out) == (1, "")
    assert err.startswith(f"{spec}@nosuchrev: cannot read it from git: ")
    assert len(err.splitlines()) == 1


def test_a_revision_is_never_read_as_a_git_option(
    capsys: pytest.CaptureFixture[str], spec_in_repository: Path, tmp_path: Path
) -> None:
    spec = spec_in_repository
    code, _, err = run(capsys, "diff", f"{spec}@--output={tmp_path / 'x'}", str(spec))
    assert code == 1 and "is not a revision; name a commit, branch or tag" in err
    assert not list(tmp_path.glob("x*"))


def test_panda_against_a_softer_variant(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')
    soft = write(
        "panda_soft.yaml",
        'name: PandaSoft\nextends: Panda\njoints:\n  - {match: "joint[1-5]", damping: 0.3}\n',
    )
    code, out, _ = run(capsys, "diff", "Panda", str(soft))
    lines = rows(out)
    assert code == 0
    assert ["name", "Panda", "->", "PandaSoft"] in lines
    assert ["joints[0].damping", "0.1", "->", "0.3"] in lines
    assert ["joint", "robot0_joint1", "damping", "0.1", "->", "0.3"] in lines
    assert ["joint", "robot0_joint6", "damping"] not in [line[:3] for line in lines]
