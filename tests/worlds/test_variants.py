"""Variants: a grid's cartesian product, seeded draws, a manifest that matches the files, any worker count."""

from __future__ import annotations

import hashlib
import itertools
import json
import signal
import subprocess
import sys
import time
from pathlib import Path
from typing import Any

import mujoco
import pytest

import assembler
from assembler.cli import main
from assembler.compiler.service import wait_for_writes
from assembler.mjcf.emit import XmlText
from assembler.worlds.variants import Grid, VariantPlan, write_variants
from assembler.worlds.variants.effects import same_model
from assembler.worlds.variants.run import counts as variant_counts
from assembler.worlds.variants.run import variant_model, variants_surely_differ
from tests.conftest import use_private_cache
from tests.patch.test_patchable import CASES, Write, _register_declared
from tests.patch.test_patched_api import _differences, _no_compile


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
    assert (stdout, err.startswith("wrote 6 of 6 variants of Finch6 to ")) == ("", True)
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
    assert stdout == ""
    assert err.startswith("wrote 2 of 3 variants of Finch6")
    assert err.split("\n", 1)[1] == (
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


def test_variants_are_kept_in_the_cache_only_when_asked_in_every_worker(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    cache = tmp_path / "cache"
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(cache))
    monkeypatch.delenv("ASSEMBLER_NO_CACHE", raising=False)
    grid = ["variants", "Sparrow7", "--grid", "joint_defaults.damping=0.05,0.1", "--jobs", "2"]
    assert main([*grid, "-o", str(tmp_path / "a")]) == 0
    assert not cache.exists() or not any(cache.glob("*.mjb"))  # a sweep's models: not kept by default
    assert main([*grid, "-o", str(tmp_path / "b"), "--cache"]) == 0
    # Entries: the two variants, and the robot without the swept field they were written from (its
    # text, with the values written in, is each variant's file whatever the cache held). Manifests are
    # counted: two workers storing one entry at once may leave a model file the next eviction removes.
    assert len(list(cache.glob("*.json"))) == 3


SHADOWED = "joints=[{match: '*', damping: 1.0}]"
"""Every joint's damping set by a joint override: the damping rule then changes nothing."""


def test_a_varied_field_that_changes_nothing_is_named_and_identical_models_are_counted(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = variants(
        capsys,
        "Sparrow7",
        "--set",
        SHADOWED,
        "--random",
        "4",
        "--uniform",
        "joint_defaults.damping=0.1:0.2",
        "-o",
        str(tmp_path / "dr"),
    )
    assert code == 0 and out == ""
    summary, _, err = err.partition("\n")  # "wrote ...", on stderr as every command's
    assert summary.endswith(": 1 distinct model")
    assert err == (
        "warning: --uniform joint_defaults.damping changes nothing in the compiled model (variants that differ "
        "only in it are byte-identical); see what else in the spec sets it\n"
    )
    assert len({line["sha256"] for line in manifest(tmp_path / "dr")}) == 1


def test_of_two_varied_fields_only_the_idle_one_is_named(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    code, out, err = variants(
        capsys,
        "Sparrow7",
        "--set",
        SHADOWED,
        "--grid",
        "joint_defaults.damping=0.1,0.2",
        "--grid",
        "joint_defaults.frictionloss=0.0,0.3",
        "-o",
        str(tmp_path / "grid"),
    )
    assert code == 0 and out == ""
    summary, _, err = err.partition("\n")
    assert summary.endswith(": 2 distinct models")
    assert err.startswith("warning: --grid joint_defaults.damping changes nothing") and err.count("\n") == 1


@pytest.mark.parametrize("cached", [(), ("--set", SHADOWED), ("--set", "joint_defaults.damping=0.3")])
def test_a_set_that_changes_nothing_in_a_build_is_a_warning(
    cached: tuple[str, ...],
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    monkeypatch: pytest.MonkeyPatch,
) -> None:
    use_private_cache(tmp_path / "cache", monkeypatch)
    # whatever the cache holds: with the plain robot cached, a variant is patched onto it, and the
    # comparison then sees a patched model beside a compiled one (equal to 1e-10, not to the bit)
    for arguments in {(), cached}:
        assert main(["build", "Sparrow7", *arguments, "-o", str(tmp_path / "before.xml")]) == 0
    wait_for_writes()
    capsys.readouterr()
    out = tmp_path / "soft.xml"
    argv = ["build", "Sparrow7", "--set", SHADOWED, "--set", "joint_defaults.damping=0.3", "-o", str(out)]
    assert main(argv) == 0
    assert capsys.readouterr().err.splitlines() == [
        f"wrote {out}",
        "warning: --set joint_defaults.damping changes nothing in the compiled model; see what else in the spec sets it",
    ]


def test_a_new_run_never_leaves_the_old_manifest_beside_new_files(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    folder = tmp_path / "sweep"
    assert (
        variants(capsys, "Sparrow7", "--grid", "joint_defaults.damping=0.1,0.2,0.3", "-o", str(folder))[0]
        == 0
    )
    # A second run with a failing variant: whatever it writes, the manifest describes exactly that.
    code, _, _ = variants(capsys, "Sparrow7", "--grid", "joint_defaults.damping=-1,0.5", "-o", str(folder))
    assert code == 1
    for line in manifest(folder):
        assert hashlib.sha256((folder / str(line["file"])).read_bytes()).hexdigest() == line["sha256"]
    assert [line["overrides"] for line in manifest(folder)] == [{"joint_defaults.damping": 0.5}]


CLI = "import sys; from assembler.cli import run; sys.exit(run())"


def _children(pid: int) -> set[int]:
    found = set()
    for status in Path("/proc").glob("[0-9]*/stat"):
        try:
            fields = status.read_text().rsplit(")", 1)[1].split()
        except OSError:
            continue
        if int(fields[1]) == pid:
            found.add(int(status.parent.name))
    return found


@pytest.mark.skipif(not Path("/proc/self/stat").exists(), reason="needs /proc to find the workers")
def test_workers_exit_when_the_run_is_killed_and_an_interrupted_run_leaves_a_true_manifest(
    tmp_path: Path,
) -> None:
    # A description per variant: not a patchable field, so every variant is compiled and the run is
    # still building when it is interrupted (a patchable grid is written in milliseconds per variant).
    values = ",".join(f"run{index}" for index in range(300))
    command = subprocess.Popen(
        [sys.executable, "-c", CLI, "variants", "Biped", "--grid", f"description={values}"]
        + ["--jobs", "2", "-o", "out"],
        cwd=tmp_path,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.DEVNULL,
    )
    deadline = time.monotonic() + 60
    while len(_children(command.pid)) < 2 and time.monotonic() < deadline:
        time.sleep(0.05)
    workers = _children(command.pid)
    assert len(workers) >= 2
    time.sleep(1.0)
    command.send_signal(signal.SIGKILL)
    command.wait()
    deadline = time.monotonic() + 10
    while (
        any(Path(f"/proc/{pid}").exists() and _is_running(pid) for pid in workers)
        and time.monotonic() < deadline
    ):
        time.sleep(0.1)
    assert not [pid for pid in workers if Path(f"/proc/{pid}").exists() and _is_running(pid)]
    # Killed outright, the run wrote no manifest: none can name a file that is not there.
    assert not (tmp_path / "out" / "manifest.jsonl").exists()


def _is_running(pid: int) -> bool:
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def _one_variant(robot: str, overrides: dict[str, Any]) -> VariantPlan:
    """A plan whose one variant is ``robot`` with ``overrides`` (each a one-value grid)."""
    return VariantPlan(robot, grids=tuple(Grid(key, (value,)) for key, value in overrides.items()), jobs=1)


@pytest.mark.parametrize(
    ("robot", "overrides"), CASES, ids=[next(iter(o)) + f"-{i}" for i, (_, o) in enumerate(CASES)]
)
def test_each_variant_file_loads_to_the_model_of_its_full_compile(
    write: Write, tmp_path: Path, robot: str, overrides: dict[str, Any]
) -> None:
    _register_declared(write)
    edited = variant_counts.edited
    run = write_variants(_one_variant(robot, overrides), tmp_path / "out")
    assert [result.problems for result in run.results] == [()]
    written = mujoco.MjModel.from_xml_path(str(tmp_path / "out" / str(run.results[0].file)))
    compiled = assembler.assemble(robot, overrides=overrides).get_model(cache=False, store=False)
    for model in (written, compiled):  # MuJoCo's writer writes a sphere's one size; the rest is unused
        model.site_size[model.site_type == mujoco.mjtGeom.mjGEOM_SPHERE, 1:] = 0.0
    assert _differences(written, compiled) == []
    by_text = not any(key.startswith("bodies") for key in overrides)  # bodies: scales are compiled
    assert variant_counts.edited == edited + by_text


@pytest.mark.parametrize(
    ("grid", "attribute", "refused"),
    [
        ("actuators[0].ctrlrange=[1, 1],[-1, 1]", "ctrlrange", "1 1"),
        ("actuators[0].forcerange=[5, -5],[-5, 5]", "forcerange", "5 -5"),
    ],
)
def test_a_value_mujoco_refuses_is_refused_before_writing_and_the_edited_text_would_not_load(
    write: Write,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
    grid: str,
    attribute: str,
    refused: str,
) -> None:
    _register_declared(write)
    out = tmp_path / "out"
    code, _, err = variants(capsys, "Declared", "--grid", grid, "-o", str(out), "--jobs", "1")
    assert code == 1 and err.split("\n")[1].startswith("variant 0 (")  # reported, by the schema's check
    assert [line["index"] for line in manifest(out)] == [1]
    assert sorted(files(out)) == ["Declared_0001.xml", "manifest.jsonl"]
    # The same value put into the written text: MuJoCo's compiler refuses it too.
    text = XmlText((out / "Declared_0001.xml").read_text()).edited(
        {("general", "robot0_shoulder"): {attribute: refused}}
    )
    with pytest.raises(ValueError):
        mujoco.MjModel.from_xml_string(text)


def test_a_grid_of_joint_values_is_written_in_this_process_by_default(tmp_path: Path) -> None:
    edited = variant_counts.edited
    plan = VariantPlan("Sparrow7", grids=(Grid.parse("joint_defaults.frictionloss=0.1,0.2,0.3"),))
    run = write_variants(plan, tmp_path / "out")
    assert len(run.written) == 3 and run.distinct == 3
    assert variant_counts.edited == edited + 3  # here, not in worker processes


def test_variants_of_a_robot_whose_model_and_xml_are_cached_compile_nothing(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    use_private_cache(tmp_path / "cache", monkeypatch)
    assembler.assemble("Finch6").get_xml()  # an entry with the model and its XML, as `build -o` leaves
    wait_for_writes()
    overrides = {"joint_defaults.damping": 0.33}
    compiled = assembler.assemble("Finch6", overrides=overrides).get_model(cache=False, store=False)
    with monkeypatch.context() as tripwire:
        _no_compile(tripwire)
        run = write_variants(_one_variant("Finch6", overrides), tmp_path / "out")
    written = mujoco.MjModel.from_xml_path(str(tmp_path / "out" / str(run.results[0].file)))
    assert _differences(written, compiled) == []


def test_the_models_a_sweep_compares_in_memory_are_the_models_its_files_load_to(tmp_path: Path) -> None:
    """Which varied fields changed nothing is decided on models patched in memory (no text loaded);
    each must be the model its written file loads to, or a field's effect is misjudged."""
    plan = VariantPlan(
        "Sparrow7",
        grids=(
            Grid.parse("joint_defaults.damping=0.1,0.4"),
            Grid.parse("joint_defaults.frictionloss=0.0,0.3"),
            Grid.parse("joints=[{match: joint2, armature: 0.02}],[{match: joint2, armature: 0.2}]"),
        ),
    )
    run = write_variants(plan, tmp_path)
    assert run.no_effect == [] and len(run.written) == 8
    models = []
    for result in run.written:
        patched = variant_model(plan, plan.variant(result.index))
        assert patched is not None, "an edited variant's model is patched, not loaded"
        loaded = mujoco.MjModel.from_xml_path(str(tmp_path / str(result.file)))
        assert same_model(patched, loaded), result.index
        models.append(patched)
    assert not any(same_model(models[0], other) for other in models[1:])
    # told apart from their patches alone, as the loaded models are (and a variant from itself never)
    variants = [plan.variant(result.index) for result in run.written]
    for first, second in itertools.combinations(range(len(variants)), 2):
        assert variants_surely_differ(plan, variants[first], variants[second]), (first, second)
    assert not variants_surely_differ(plan, variants[0], dict(variants[0]))
