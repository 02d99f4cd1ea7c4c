"""Variants: a grid's cartesian product, seeded draws, a manifest that matches the files, any worker count."""

from __future__ import annotations

import hashlib
import json
from pathlib import Path

import mujoco
import pytest

from assembler.cli import main


def variants(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(["variants", *argv])
    captured = capsys.readouterr()
    return code, captured.out, captured.err


def manifest(folder: Path) -> list[dict[str, object]]:
    return [json.loads(line) for line in (folder / "manifest.jsonl").read_text().splitlines()]


def files(folder: Path) -> dict[str, bytes]:
    return {path.name: path.read_bytes() for path in sorted(folder.iterdir())}


GRID = ("--grid", "joint_defaults.damping=0.05,0.1,0.2", "--grid", "joint_defaults.frictionloss=0,0.1")
DRAWS = ("--random", "4", "--uniform", "joint_defaults.damping=0.05:0.2", "--normal", "init_qpos[3]=-2.0:0.1")


def test_a_grid_writes_its_cartesian_product_with_a_manifest_that_matches_the_files(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    out = tmp_path / "out"
    code, stdout, err = variants(capsys, "Finch6", *GRID, "-o", str(out), "--jobs", "1")
    assert code == 0, err
    assert stdout.startswith("wrote 6 of 6 variants of Finch6 to ")
    lines = manifest(out)
    assert [line["index"] for line in lines] == list(range(6))
    assert [line["overrides"] for line in lines][:2] == [
        {"joint_defaults.damping": 0.05, "joint_defaults.frictionloss": 0},
        {"joint_defaults.damping": 0.05, "joint_defaults.frictionloss": 0.1},
    ]
    assert sorted(files(out)) == sorted([str(line["file"]) for line in lines] + ["manifest.jsonl"])
    for line in lines:
        path = out / str(line["file"])
        assert hashlib.sha256(path.read_bytes()).hexdigest() == line["sha256"]
        model = mujoco.MjModel.from_xml_path(str(path))
        values = line["overrides"]
        assert isinstance(values, dict)
        assert model.joint("robot0_joint1").damping[0] == pytest.approx(values["joint_defaults.damping"])
        assert model.joint("robot0_joint1").frictionloss == pytest.approx(
            values["joint_defaults.frictionloss"]
        )


def test_the_same_seed_gives_the_same_files_and_another_seed_other_files(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    runs = {}
    for name, seed in (("a", "7"), ("b", "7"), ("c", "8")):
        code, _, err = variants(
            capsys, "Finch6", *DRAWS, "--seed", seed, "-o", str(tmp_path / name), "--jobs", "1"
        )
        assert code == 0, err
        runs[name] = files(tmp_path / name)
    assert runs["a"] == runs["b"]
    assert runs["a"].keys() == runs["c"].keys() and runs["a"] != runs["c"]
    lines = manifest(tmp_path / "a")
    assert all(line["seed"] == 7 for line in lines)
    dampings = [line["overrides"]["joint_defaults.damping"] for line in lines]  # type: ignore[index]
    assert len(set(dampings)) == 4 and all(0.05 <= d <= 0.2 for d in dampings)


def test_two_workers_write_exactly_what_one_writes(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    for name, jobs in (("serial", "1"), ("parallel", "2")):
        code, _, err = variants(
            capsys, "Finch6", *GRID[2:], *DRAWS, "-o", str(tmp_path / name), "--jobs", jobs
        )
        assert code == 0, err
    assert len(manifest(tmp_path / "serial")) == 8  # 2 grid points x 4 draws
    assert files(tmp_path / "serial") == files(tmp_path / "parallel")


def test_workers_build_a_robot_given_as_a_spec_file(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, two_link: Path
) -> None:
    out = tmp_path / "out"
    code, _, err = variants(
        capsys, str(two_link), "--grid", "init_qpos[1]=0.1,0.2,0.3", "-o", str(out), "--jobs", "2"
    )
    assert code == 0, err
    qpos = [
        mujoco.MjModel.from_xml_path(str(out / str(line["file"]))).key("home").qpos[1]
        for line in manifest(out)
    ]
    assert qpos == pytest.approx([0.1, 0.2, 0.3])


def test_a_failing_variant_is_reported_and_the_others_are_written(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    out = tmp_path / "out"
    code, stdout, err = variants(
        capsys, "Finch6", "--grid", "joint_defaults.damping=0.1,-1,0.2", "-o", str(out)
    )
    assert code == 1
    assert stdout.startswith("wrote 2 of 3 variants of Finch6")
    assert err == (
        "variant 1 (joint_defaults.damping=-1): --grid joint_defaults.damping: expected a non-negative number, "
        "a list of them (one per joint), a mapping 'inverse_index: <scale>' or null, got -1\n"
    )
    assert [line["index"] for line in manifest(out)] == [0, 2]
    assert sorted(files(out)) == ["Finch6_0000.xml", "Finch6_0002.xml", "manifest.jsonl"]


@pytest.mark.parametrize(
    ("flags", "message"),
    [
        (
            ("--grid", "joint_defaults.dampin=1,2"),
            "--grid joint_defaults.dampin: unknown key 'dampin'. Did you mean 'damping'? "
            "Valid keys here: armature, damping, frictionloss",
        ),
        (
            ("--grid", "joint_defaults.damping"),
            "--grid expects PATH=V1,V2,... (e.g. joint_defaults.damping=0.05,0.1), got 'joint_defaults.damping'",
        ),
        (
            ("--random", "3", "--uniform", "joint_defaults.damping=2:1"),
            "--uniform expects PATH=LOW:HIGH with LOW <= HIGH, got 'joint_defaults.damping=2:1'",
        ),
        (
            ("--uniform", "joint_defaults.damping=1:2"),
            "--uniform/--normal draw values for --random N variants; add --random N",
        ),
        ((), "nothing to vary: give --grid PATH=V1,V2,... or --random N with ranges"),
        (
            ("--grid", "joint_defaults.damping=1,2", "--set", "joint_defaults.frictionloss=x"),
            "--set joint_defaults.frictionloss: expected a non-negative number",
        ),
    ],
)
def test_flag_mistakes_stop_before_anything_is_written(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, flags: tuple[str, ...], message: str
) -> None:
    out = tmp_path / "out"
    code, _, err = variants(capsys, "Finch6", *flags, "-o", str(out))
    assert code == 1 and not out.exists()
    assert err.startswith(message) and len(err.splitlines()) == 1


def test_no_cache_reaches_the_worker_processes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    cache = tmp_path / "cache"
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(cache))
    monkeypatch.delenv("ASSEMBLER_NO_CACHE", raising=False)
    grid = ["variants", "Sparrow7", "--grid", "joint_defaults.damping=0.05,0.1", "--jobs", "2"]
    assert main([*grid, "-o", str(tmp_path / "a"), "--no-cache"]) == 0
    assert not cache.exists() or not any(cache.iterdir())
    assert main([*grid, "-o", str(tmp_path / "b")]) == 0
    assert any(cache.glob("*.mjb"))
