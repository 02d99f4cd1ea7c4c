"""Sweeps sharded for a cluster: the shards of a plan write what the whole run writes, a merge checks
that they cover it exactly once, and a huge plan states its size without enumerating it."""

from __future__ import annotations

import itertools
import json
from pathlib import Path

import numpy as np
import pytest

from assembler.cli import main
from assembler.worlds.variants import Draw, Grid, VariantPlan

PLAN = (
    "Sparrow7",
    "--grid",
    "joint_defaults.damping=0.05,0.1,0.2",
    "--random",
    "2",
    "--seed",
    "3",
    "--uniform",
    "joint_defaults.frictionloss=0:0.2",
)


def run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str]:
    code = main(["variants", *argv, "--jobs", "1"])
    return code, capsys.readouterr().err


def test_variants_are_numbered_as_the_cartesian_product_with_draws_seeded_by_index() -> None:
    plan = VariantPlan(
        "Sparrow7",
        grids=(Grid.parse("joint_defaults.damping=0.1,0.2,0.3"), Grid.parse("joint_defaults.armature=1,2")),
        draws=(Draw.parse("joint_defaults.frictionloss=0:1", "uniform"),),
        random=3,
        seed=7,
    )
    points = list(itertools.product((0.1, 0.2, 0.3), (1, 2)))
    assert plan.size == 18
    for index in range(plan.size):
        damping, armature = points[index // 3]
        drawn = float(np.random.default_rng([7, index]).uniform(0, 1))
        assert plan.variant(index) == {
            "joint_defaults.damping": damping,
            "joint_defaults.armature": armature,
            "joint_defaults.frictionloss": drawn,
        }
    shards = [plan.shard(i, 4) for i in range(1, 5)]
    assert [index for shard in shards for index in shard] == list(range(18))
    assert sorted(len(shard) for shard in shards) == [4, 4, 5, 5]


def test_shards_in_one_folder_merge_into_the_files_and_manifest_of_the_whole_run(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    whole, sharded = tmp_path / "whole", tmp_path / "sharded"
    assert run(capsys, *PLAN, "-o", str(whole))[0] == 0
    for number in (3, 1, 2):  # any order, as a scheduler starts them
        code, err = run(capsys, *PLAN, "-o", str(sharded), "--shard", f"{number}/3")
        assert code == 0 and f"manifest-shard-{number}-of-3.jsonl" in err, err
    code, err = run(capsys, *PLAN, "-o", str(sharded), "--merge", "3")
    assert code == 0 and "merged 3 shards of Sparrow7" in err and "lists 6" in err, err
    assert (sharded / "manifest.jsonl").read_text() == (whole / "manifest.jsonl").read_text()
    for line in (whole / "manifest.jsonl").read_text().splitlines():
        name = json.loads(line)["file"]
        assert (sharded / name).read_bytes() == (whole / name).read_bytes()


def test_a_merge_names_each_missing_foreign_or_changed_shard_and_writes_no_manifest(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    out = tmp_path / "out"
    assert run(capsys, *PLAN, "-o", str(out), "--shard", "1/3")[0] == 0
    other_seed = [*PLAN[:-3], "4", *PLAN[-2:]]
    assert run(capsys, *other_seed, "-o", str(out), "--shard", "2/3")[0] == 0
    code, err = run(capsys, *PLAN, "-o", str(out), "--merge", "3")
    assert code == 1 and not (out / "manifest.jsonl").exists()
    assert err.splitlines() == [
        "shard-2-of-3: written for another plan (other flags, seed or robot); "
        "run it: assembler variants ... --shard 2/3",
        f"shard-3-of-3: not in {out}; run it: assembler variants ... --shard 3/3",
    ]
    assert run(capsys, *PLAN, "-o", str(out), "--shard", "2/3")[0] == 0
    assert run(capsys, *PLAN, "-o", str(out), "--shard", "3/3")[0] == 0
    first = json.loads((out / "manifest-shard-1-of-3.jsonl").read_text().splitlines()[0])["file"]
    (out / first).write_text("<mujoco/>")
    code, err = run(capsys, *PLAN, "-o", str(out), "--merge", "3")
    assert (code, err.strip()) == (
        1,
        f"{first}: missing or changed since shard-1-of-3 wrote it; run it again",
    )


@pytest.mark.parametrize("shard", ["0/3", "4/3", "3", "a/b"])
def test_a_shard_outside_its_plan_is_one_line(
    capsys: pytest.CaptureFixture[str], tmp_path: Path, shard: str
) -> None:
    code, err = run(capsys, *PLAN, "-o", str(tmp_path / "out"), "--shard", shard)
    assert (code, err.strip()) == (1, f"--shard {shard}: expected I/N with 1 <= I <= N, e.g. 3/10")


def test_a_huge_plan_states_its_size_and_a_shard_of_it_writes_without_enumerating_it(
    capsys: pytest.CaptureFixture[str], tmp_path: Path
) -> None:
    huge = ("Sparrow7", "--random", "100000000", "--uniform", "joint_defaults.damping=0.05:0.2")
    code, err = run(capsys, *huge, "-o", str(tmp_path), "--shard", "100000000/100000000")
    assert code == 0, err
    assert err.splitlines()[0] == (
        "a plan of 100,000,000 variants of Sparrow7; shard 100000000/100000000: 1 of them"
    )
    (line,) = (tmp_path / "manifest-shard-100000000-of-100000000.jsonl").read_text().splitlines()
    drawn = float(np.random.default_rng([0, 99_999_999]).uniform(0.05, 0.2))
    assert json.loads(line)["index"] == 99_999_999
    assert json.loads(line)["overrides"] == {"joint_defaults.damping": drawn}
