"""robot-assembler.lock: every file a robot's build reads, by sha256, and `validate --locked` naming
each file that drifted with the robots it affects."""

from __future__ import annotations

import hashlib
import shutil
import subprocess
from pathlib import Path

import pytest

from assembler.cli import main
from assembler.urdf.packages import package_folders

REPOSITORY = Path(__file__).resolve().parents[2]


@pytest.fixture
def lab(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A scratch spec repository holding one arm (Sparrow7's spec and MJCF, renamed Arm7)."""
    (tmp_path / ".git").mkdir()
    (tmp_path / "pyproject.toml").write_text("[tool.robot-assembler]\n")
    shutil.copytree(REPOSITORY / "assets" / "sparrow7", tmp_path / "assets" / "sparrow7")
    (tmp_path / "specs").mkdir()
    spec = (REPOSITORY / "specs" / "sparrow7.yaml").read_text().replace("name: Sparrow7\n", "name: Arm7\n")
    (tmp_path / "specs" / "arm7.yaml").write_text(spec)
    monkeypatch.chdir(tmp_path)
    return tmp_path


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_a_lock_lists_the_spec_model_and_parts_each_robot_reads_and_holds_while_nothing_changes(
    capsys: pytest.CaptureFixture[str], lab: Path
) -> None:
    code, _, err = run(capsys, "lock")
    assert (code, err) == (0, "wrote robot-assembler.lock: 6 files of 1 robot\n")
    lines = (lab / "robot-assembler.lock").read_text().splitlines()
    assert "robot Arm7" in lines and any(line.startswith("mujoco ") for line in lines)
    named = {tuple(line.split()[:2]) for line in lines if line.startswith("  ")}
    assert {("spec", "specs/arm7.yaml"), ("model", "assets/sparrow7/sparrow7.xml")} <= named
    assert ("spec", "shipped:specs/bases/pedestal.yaml") in named  # its default base, wherever installed
    assert run(capsys, "validate", "--locked") == (
        0,
        "robot-assembler.lock: the 6 files it lists are unchanged\n",
        "",
    )
    assert run(capsys, "lock")[0] == 0 and (lab / "robot-assembler.lock").read_text().splitlines() == lines


def test_a_changed_or_removed_file_is_one_line_with_both_digests_and_the_robots_it_affects(
    capsys: pytest.CaptureFixture[str], lab: Path
) -> None:
    assert run(capsys, "lock")[0] == 0
    model = lab / "assets" / "sparrow7" / "sparrow7.xml"
    old = next(
        line.split()[2]
        for line in (lab / "robot-assembler.lock").read_text().splitlines()
        if "sparrow7.xml" in line
    )
    model.write_text(model.read_text() + "<!-- edited -->\n")
    new = hashlib.sha256(model.read_bytes()).hexdigest()
    code, out, err = run(capsys, "validate", "--locked")
    assert (code, out) == (1, "")
    assert err.splitlines() == [
        f"assets/sparrow7/sparrow7.xml: sha256 {old[:12]} in the lock, sha256 {new[:12]} now; affects Arm7",
        "robot-assembler.lock: run `assembler lock` to accept these changes",
    ]
    (lab / "specs" / "arm7.yaml").unlink()
    code, _, err = run(capsys, "validate", "--locked")
    assert code == 1 and "specs/arm7.yaml: sha256 " in err and "in the lock, gone; affects Arm7" in err


def test_a_urdf_robot_locks_its_package_files_and_version(
    capsys: pytest.CaptureFixture[str], lab: Path
) -> None:
    if not package_folders("example-robot-data"):
        pytest.skip('example-robot-data is not installed: pip install -e ".[urdf]"')
    ur5 = (REPOSITORY / "specs" / "urdf" / "ur5.yaml").read_text().replace("name: UR5\n", "name: LabUR5\n")
    (lab / "specs" / "lab_ur5.yaml").write_text(ur5)
    assert run(capsys, "lock", "specs/lab_ur5.yaml")[0] == 0
    text = (lab / "robot-assembler.lock").read_text()
    assert "  package example-robot-data " in text
    assert "  model package://example-robot-data/robots/ur_description/urdf/ur5_robot.urdf " in text
    assert "converted-meshes" not in text  # the cache's copies are derived from the .dae listed
    assert run(capsys, "validate", "--locked")[0] == 0


def test_without_a_lock_or_outside_a_repository_it_is_one_line(
    capsys: pytest.CaptureFixture[str], lab: Path, tmp_path_factory: pytest.TempPathFactory
) -> None:
    assert run(capsys, "validate", "--locked") == (
        1,
        "",
        "robot-assembler.lock: no lock here; write one with `assembler lock`\n",
    )
    (lab / "robot-assembler.lock").write_text("mujoco 4\nrobot A\n  spec a.yaml\n")
    code, _, err = run(capsys, "validate", "--locked")
    assert (code, err) == (
        1,
        "robot-assembler.lock:3:1: not a line of a lock file; write it again with `assembler lock`\n",
    )


def test_diff_of_two_locks_shows_the_robots_a_change_affects_with_each_file(
    capsys: pytest.CaptureFixture[str], lab: Path
) -> None:
    git = ["git", "-c", "user.name=t", "-c", "user.email=t@t", "-c", "commit.gpgsign=false"]
    shutil.rmtree(lab / ".git")
    subprocess.run([*git, "init", "-q"], cwd=lab, check=True)
    assert run(capsys, "lock")[0] == 0
    subprocess.run([*git, "add", "-A"], cwd=lab, check=True)
    subprocess.run([*git, "commit", "-q", "-m", "locked"], cwd=lab, check=True)
    model = lab / "assets" / "sparrow7" / "sparrow7.xml"
    old = hashlib.sha256(model.read_bytes()).hexdigest()
    model.write_text(model.read_text() + "<!-- edited -->\n")
    new = hashlib.sha256(model.read_bytes()).hexdigest()
    assert run(capsys, "lock")[0] == 0
    code, out, _ = run(capsys, "diff", "robot-assembler.lock@HEAD", "robot-assembler.lock", "--exit-code")
    assert (code, out.splitlines()) == (
        1,
        ["robot Arm7: 1 change", f"  model assets/sparrow7/sparrow7.xml: {old[:12]} -> {new[:12]}"],
    )
    assert (
        run(capsys, "diff", "robot-assembler.lock", "robot-assembler.lock")[1] == "the locks are the same\n"
    )
