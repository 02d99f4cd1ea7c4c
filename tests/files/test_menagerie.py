"""MuJoCo Menagerie by name: ``assembler new menagerie:NAME`` writes a spec reading the model from the
mujoco-menagerie library's MENAGERIE_ROOT or cache (never downloading), naming its git tree id; a
missing, changed or other-version model is one line saying what to run; the lock records the id."""

from __future__ import annotations

import hashlib
import json
import shutil
from pathlib import Path

import mujoco
import pytest

from assembler.cli import main

menagerie = pytest.importorskip("mujoco_menagerie", reason='pip install -e ".[menagerie]"')

ROOT = Path(__file__).resolve().parents[2]
NAME = "universal_robots_ur5e"


@pytest.fixture
def tree(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A MENAGERIE_ROOT with one model folder of real files (Sparrow7's MJCF as the UR5e's entry
    file), and a working folder that is a spec repository."""
    root = tmp_path / "menagerie"
    (root / NAME).mkdir(parents=True)
    shutil.copy(ROOT / "assets" / "sparrow7" / "sparrow7.xml", root / NAME / "ur5e.xml")
    work = tmp_path / "lab"
    (work / ".git").mkdir(parents=True)
    (work / "pyproject.toml").write_text('[tool.robot-assembler]\nspecs = ["."]\n')
    monkeypatch.setenv("MENAGERIE_ROOT", str(root))
    monkeypatch.chdir(work)
    return root


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def test_new_by_name_writes_a_spec_naming_the_model_and_its_id_that_builds_the_file_as_mujoco_loads_it(
    capsys: pytest.CaptureFixture[str], tree: Path
) -> None:
    oid = menagerie.get(NAME).oid
    code, out, err = run(capsys, "new", f"menagerie:{NAME}", "-o", "ur5e.yaml")
    assert code == 0, err
    assert (
        out.splitlines()[0] == f"menagerie:{NAME}: {tree / NAME / 'ur5e.xml'} (BSD-3-Clause, oid {oid[:12]})"
    )
    assert f"mjcf: menagerie://{NAME}@{oid[:12]}/ur5e.xml" in Path("ur5e.yaml").read_text()
    assert run(capsys, "build", "ur5e.yaml", "--no-base", "--no-grippers", "-o", "ur5e.xml")[0] == 0
    ours, theirs = (
        mujoco.MjModel.from_xml_path("ur5e.xml"),
        mujoco.MjModel.from_xml_path(str(tree / NAME / "ur5e.xml")),
    )
    assert (ours.njnt, ours.nu) == (theirs.njnt, theirs.nu)
    assert run(capsys, "lock")[0] == 0
    lock = Path("robot-assembler.lock").read_text()
    assert f"  package menagerie:{NAME} {oid}\n" in lock
    assert f"  model menagerie://{NAME}@{oid[:12]}/ur5e.xml " in lock


def test_a_spec_for_another_version_of_the_model_is_one_line(
    capsys: pytest.CaptureFixture[str], tree: Path
) -> None:
    oid = menagerie.get(NAME).oid
    Path("old.yaml").write_text(
        Path(ROOT / "specs" / "sparrow7.yaml")
        .read_text()
        .replace("name: Sparrow7\n", "name: OldUr5e\n")
        .replace("mjcf: ../assets/sparrow7/sparrow7.xml", f"mjcf: menagerie://{NAME}@0123456789ab/ur5e.xml")
    )
    code, _, err = run(capsys, "build", "old.yaml", "-o", "old.xml")
    assert code == 1 and not Path("old.xml").exists()
    assert err.strip().endswith(
        f"written for {NAME} at 0123456789ab; mujoco-menagerie {menagerie.__version__} serves {oid[:12]}: "
        f"install the version that serves it, or run assembler new menagerie:{NAME} again and review the change"
    )


def test_a_model_not_downloaded_unknown_or_changed_since_its_download_is_one_line(
    capsys: pytest.CaptureFixture[str], tree: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    assert run(capsys, "new", "menagerie:franka_emika_panda")[2] == (
        f"menagerie:franka_emika_panda: franka_emika_panda is not in MENAGERIE_ROOT={tree}\n"
    )
    monkeypatch.delenv("MENAGERIE_ROOT")
    monkeypatch.setenv("MENAGERIE_CACHE_DIR", str(tmp_path / "cache"))
    assert run(capsys, "new", f"menagerie:{NAME}")[2] == (
        f"menagerie:{NAME}: {NAME} is not downloaded; run: python -m mujoco_menagerie prefetch {NAME} "
        "(or set MENAGERIE_ROOT to a Menagerie checkout)\n"
    )
    code, _, err = run(capsys, "new", "menagerie:ur5e_typo")
    assert code == 1 and err.startswith("menagerie:ur5e_typo: ") and len(err.splitlines()) == 1
    # a download as the library publishes it (its sentinel lists each file's sha256), then edited
    robot = menagerie.get(NAME)
    folder = Path(menagerie.Cache().model_path(robot))
    folder.mkdir(parents=True)
    shutil.copy(tree / NAME / "ur5e.xml", folder / "ur5e.xml")
    digest = hashlib.sha256((folder / "ur5e.xml").read_bytes()).hexdigest()
    (folder / ".complete").write_text(json.dumps({"oid": robot.oid, "files": {"ur5e.xml": digest}}))
    assert run(capsys, "new", f"menagerie:{NAME}", "-o", "cached.yaml")[0] == 0
    (folder / "ur5e.xml").write_text((folder / "ur5e.xml").read_text() + "<!-- edited -->")
    assert run(capsys, "new", f"menagerie:{NAME}", "-o", "edited.yaml")[2] == (
        f"menagerie:{NAME}: 1 files of the downloaded {NAME} changed since the download (first ur5e.xml); "
        f"run: python -m mujoco_menagerie clear, then prefetch {NAME}\n"
    )
