"""The compiled-model cache: a hit equals a fresh compile; every input change is a miss; touching a
file is not; it can be switched off, stays within its size, shrugs off broken entries, and two
processes can fill one entry at once. Every test uses its own cache folder, never the user's."""

from __future__ import annotations

import json
import os
import subprocess
import sys
import textwrap
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.cli import main
from assembler.compiler import service
from assembler.compiler.service import default_store, wait_for_writes
from assembler.files.paths import package_root
from tests.conftest import MESH_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache

PARENT_SPEC = "name: MeshArm\nmjcf: meshy.xml\ninit_qpos: [0.5, -0.5]\njoint_defaults: {damping: 0.3}\n"
CHILD_SPEC = "name: MeshArmSoft\nextends: MeshArm\njoint_defaults: {armature: 0.05}\n"

COMPARED_FIELDS = (
    "body_pos",
    "body_quat",
    "body_mass",
    "body_inertia",
    "jnt_range",
    "dof_damping",
    "dof_armature",
    "dof_frictionloss",
    "geom_size",
    "geom_rgba",
    "actuator_gainprm",
    "mesh_vert",
    "key_qpos",
    "key_ctrl",
    "qpos0",
)


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A fresh cache folder per test; the working folder is the test's too, to catch MUJOCO_LOG.TXT."""
    folder = use_private_cache(tmp_path / "model-cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    yield folder
    wait_for_writes()
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()


@pytest.fixture
def mesh_arm(tmp_path: Path) -> Path:
    """A spec folder: a parent spec with a mesh, a child that extends it; returns the folder."""
    folder = tmp_path / "arm"
    (folder / "meshes").mkdir(parents=True)
    for name, text in [
        ("meshes/tet.obj", TETRAHEDRON_OBJ),
        ("meshy.xml", MESH_ARM_MJCF),
        ("mesh_arm.yaml", PARENT_SPEC),
        ("mesh_arm_soft.yaml", CHILD_SPEC),
    ]:
        edit(folder / name, text, seconds_ago=3600)
    assembler.register_specs(folder)
    return folder


def edit(path: Path, text: str, seconds_ago: float = 10) -> None:
    """Write ``path`` as a user would have some time ago: the cache does not store models made
    from files modified in the last seconds (MuJoCo's own asset cache may not have seen them)."""
    path.write_text(text)
    then = time.time() - seconds_ago
    os.utime(path, (then, then))


def lookups() -> tuple[int, int, int]:
    """(hits, misses, bypassed) so far in this process."""
    return service.counts.hits, service.counts.misses, service.counts.bypassed


def load(name: str, **kwargs: object) -> mujoco.MjModel:
    """A robot's model through the cache, with its entry written before returning."""
    model = assembler.assemble(name, **kwargs).get_model()  # type: ignore[arg-type]
    wait_for_writes()
    return model


def counted(action: Callable[[], object]) -> tuple[int, int, int]:
    """How many hits, misses and bypasses ``action`` caused."""
    before = lookups()
    action()
    wait_for_writes()
    return tuple(after - first for after, first in zip(lookups(), before, strict=True))  # type: ignore[return-value]


def fresh(name: str) -> mujoco.MjModel:
    return assembler.assemble(name).get_model(cache=False)


def assert_same_model(ours: mujoco.MjModel, reference: mujoco.MjModel) -> None:
    for size in ("nq", "nv", "nu", "nbody", "njnt", "ngeom", "nmesh", "nkey", "nsite", "nnames"):
        assert getattr(ours, size) == getattr(reference, size), size
    for field in COMPARED_FIELDS:
        assert np.array_equal(getattr(ours, field), getattr(reference, field)), field
    assert bytes(ours.names) == bytes(reference.names)


def entries(folder: Path) -> list[Path]:
    return sorted(folder.glob("*.json"))


# ----- a hit is the same model --------------------------------------------------------------


ROBOTS = ["Sparrow7"] + (["Panda"] if package_root("robosuite") else [])


@pytest.mark.parametrize("name", ROBOTS)
def test_cached_model_equals_a_fresh_compile(name: str, private_cache: Path) -> None:
    assert counted(lambda: load(name)) == (0, 1, 0)
    before = lookups()
    cached = load(name)
    assert lookups()[0] == before[0] + 1
    assert_same_model(cached, fresh(name))
    assert len(entries(private_cache)) == 1


def test_a_hit_keeps_names_xml_and_keyframe_of_a_compile() -> None:
    load("Sparrow7")
    robot = assembler.assemble("Sparrow7")
    model = robot.get_model()
    reference = assembler.assemble("Sparrow7")
    assert robot.joints == reference.joints and robot.actuators == reference.actuators
    assert robot.cameras == reference.cameras
    assert robot.get_xml() == reference.get_xml(cache=False)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    assert data.qpos[:7] == pytest.approx([0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785])


def test_build_bundle_from_a_hit_keeps_the_home_keyframe(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["build", "Sparrow7", "--bundle", "first"]) == 0
    assert main(["build", "Sparrow7", "--bundle", "second"]) == 0
    first, second = Path("first/Sparrow7.xml").read_text(), Path("second/Sparrow7.xml").read_text()
    assert '<key name="home"' in second and first == second


def test_an_edited_mjspec_is_compiled_as_edited() -> None:
    load("Sparrow7")
    robot = assembler.assemble("Sparrow7")
    robot.mjspec.joint("robot0_joint1").range = [-0.5, 0.5]
    assert counted(robot.get_model) == (0, 0, 0)  # compiled directly: the cache is not asked
    assert robot.get_model().joint("robot0_joint1").range.tolist() == [-0.5, 0.5]


# ----- every input is in the key or the manifest --------------------------------------------


def test_touching_a_mesh_without_changing_it_still_hits(mesh_arm: Path) -> None:
    load("MeshArm")
    mesh = mesh_arm / "meshes" / "tet.obj"
    later = time.time() + 60
    os.utime(mesh, (later, later))
    assert counted(lambda: load("MeshArm")) == (1, 0, 0)
    assert counted(lambda: load("MeshArm")) == (1, 0, 0)


def test_editing_a_mesh_is_a_miss_and_the_new_mesh_is_used(mesh_arm: Path) -> None:
    before = load("MeshArm")
    edit(mesh_arm / "meshes" / "tet.obj", TETRAHEDRON_OBJ.replace("v 0 0 0.1", "v 0 0 0.3"))
    assert counted(lambda: load("MeshArm")) == (0, 1, 0)
    after = load("MeshArm")
    assert not np.array_equal(after.mesh_vert, before.mesh_vert)
    assert_same_model(after, fresh("MeshArm"))


def test_repeated_loads_in_one_process_are_independent_and_still_see_edits(mesh_arm: Path) -> None:
    load("MeshArm")  # compiled and stored
    first = load("MeshArm")  # read from disk and handed over
    second = load("MeshArm")  # read again: kept in memory, a copy handed over
    second.body_mass[:] = 99.0
    third = load("MeshArm")  # a copy of the kept model
    assert_same_model(third, first)
    edit(mesh_arm / "meshes" / "tet.obj", TETRAHEDRON_OBJ.replace("v 0 0 0.1", "v 0 0 0.3"))
    assert counted(lambda: load("MeshArm")) == (0, 1, 0)


def test_a_model_from_a_file_edited_a_moment_ago_is_not_stored(mesh_arm: Path, private_cache: Path) -> None:
    (mesh_arm / "meshes" / "tet.obj").write_text(TETRAHEDRON_OBJ.replace("v 0 0 0.1", "v 0 0 0.2"))
    assert counted(lambda: load("MeshArm")) == (0, 1, 0)
    assert entries(private_cache) == []


def test_editing_the_mjcf_is_a_miss(mesh_arm: Path) -> None:
    load("MeshArm")
    xml = mesh_arm / "meshy.xml"
    edit(xml, MESH_ARM_MJCF.replace('range="-2 2"', 'range="-1 1"'))
    assembler.register_specs(mesh_arm)  # a new robot instance reads the edited file
    assert counted(lambda: load("MeshArm")) == (0, 1, 0)
    assert load("MeshArm").joint("robot0_joint2").range.tolist() == [-1, 1]


def test_editing_a_parent_spec_is_a_miss_for_the_child(mesh_arm: Path) -> None:
    assert load("MeshArmSoft").joint("robot0_joint1").damping[0] == pytest.approx(0.3)
    assembler.register_specs(mesh_arm)  # registering the same files again: same key
    assert counted(lambda: load("MeshArmSoft")) == (1, 0, 0)
    edit(mesh_arm / "mesh_arm.yaml", PARENT_SPEC.replace("0.3", "0.7"))
    assembler.register_specs(mesh_arm)
    assert counted(lambda: load("MeshArmSoft")) == (0, 1, 0)
    assert load("MeshArmSoft").joint("robot0_joint1").damping[0] == pytest.approx(0.7)


def test_a_different_spec_value_is_a_miss(mesh_arm: Path) -> None:
    load("MeshArmSoft")
    edit(mesh_arm / "mesh_arm_soft.yaml", CHILD_SPEC.replace("0.05", "0.09"))
    assembler.register_specs(mesh_arm)
    assert counted(lambda: load("MeshArmSoft")) == (0, 1, 0)
    assert load("MeshArmSoft").joint("robot0_joint2").armature == pytest.approx(0.09)


def test_changing_an_override_is_a_miss_and_repeating_it_a_hit() -> None:
    def damped(value: float) -> mujoco.MjModel:
        robot = assembler.assemble("Sparrow7", overrides={"joint_defaults.damping": value})
        model = robot.get_model()
        wait_for_writes()
        return model

    assert counted(lambda: damped(0.2)) == (0, 1, 0)
    assert counted(lambda: damped(0.3)) == (0, 1, 0)
    assert counted(lambda: damped(0.2)) == (1, 0, 0)
    assert damped(0.3).joint("robot0_joint1").damping[0] == pytest.approx(0.3)


def test_api_changes_before_get_model_are_part_of_the_key() -> None:
    load("Sparrow7")
    robot = assembler.assemble("Sparrow7")
    robot.set_joint_attribute("damping", np.full(7, 0.5))
    robot.set_base_xpos(np.array([0.5, 0.0, 0.0]))
    assert counted(robot.get_model) == (0, 1, 0)
    model = load("Sparrow7")  # the default robot is still its own entry
    changed = robot.get_model()
    assert changed.joint("robot0_joint3").damping[0] == 0.5 != model.joint("robot0_joint3").damping[0]
    assert not np.array_equal(changed.body("robot0_base").pos, model.body("robot0_base").pos)
    assert counted(lambda: load("Sparrow7", idn=1)) == (0, 1, 0)


def test_a_hand_written_subclass_is_not_cached() -> None:
    parent = assembler.REGISTERED_ROBOTS["Sparrow7"]
    handmade = type("Sparrow7Custom", (parent,), {"__module__": __name__})
    assert counted(lambda: handmade(idn=0).get_model()) == (0, 0, 1)


# ----- switching it off ---------------------------------------------------------------------


def test_no_cache_flag_compiles_and_stores_nothing(private_cache: Path) -> None:
    assert counted(lambda: main(["build", "Sparrow7", "--no-cache", "-o", "out.xml"])) == (0, 0, 1)
    assert entries(private_cache) == []
    assert counted(lambda: main(["build", "Sparrow7", "-o", "out.xml"])) == (0, 1, 0)
    assert len(entries(private_cache)) == 1


def test_environment_variable_disables_the_cache(
    private_cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ASSEMBLER_NO_CACHE", "1")
    assert counted(lambda: load("Sparrow7")) == (0, 0, 1)
    assert not private_cache.exists()


# ----- the store ----------------------------------------------------------------------------


def test_least_recently_used_entries_are_evicted_first(
    private_cache: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    load("Sparrow7", idn=0)
    one_entry = default_store().info().total_bytes
    others = sum(path.stat().st_size for path in private_cache.rglob("*") if path.is_file()) - one_entry
    # Room for two and a half models besides the other parts (decoded meshes): one bound counts all.
    monkeypatch.setenv("ASSEMBLER_CACHE_MAX_BYTES", str(int(2.5 * one_entry + others)))
    load("Sparrow7", idn=1)
    load("Sparrow7", idn=0)  # a hit: idn 0 is now more recent than idn 1
    load("Sparrow7", idn=2)  # three entries do not fit: idn 1 goes
    assert len(entries(private_cache)) == 2
    assert counted(lambda: load("Sparrow7", idn=0)) == (1, 0, 0)
    assert counted(lambda: load("Sparrow7", idn=2)) == (1, 0, 0)
    assert counted(lambda: load("Sparrow7", idn=1)) == (0, 1, 0)
    assert default_store().info().total_bytes <= 2.5 * one_entry


def test_a_truncated_model_file_is_a_miss_and_is_replaced(private_cache: Path) -> None:
    load("Sparrow7")
    (model_file,) = private_cache.glob("*.mjb")
    model_file.write_bytes(model_file.read_bytes()[:1000])
    assert counted(lambda: load("Sparrow7")) == (0, 1, 0)
    assert_same_model(load("Sparrow7"), fresh("Sparrow7"))
    assert not model_file.exists()


def test_a_byte_changed_anywhere_in_an_entry_is_a_miss_never_a_wrong_model(private_cache: Path) -> None:
    reference = fresh("Sparrow7")
    load("Sparrow7")
    (model_file,) = private_cache.glob("*.mjb")
    pristine = model_file.read_bytes()
    positions = sorted(
        {0, 1, len(pristine) // 2, len(pristine) - 1, *range(7, len(pristine), len(pristine) // 61)}
    )
    for position in positions:
        damaged = bytearray(pristine)
        damaged[position] ^= 0x01  # the smallest change: one bit
        for file in private_cache.glob("*.mjb"):
            file.unlink()
        model_file.write_bytes(bytes(damaged))
        service._recent.forget(str(private_cache))  # read from disk, not this process's memory
        assert counted(lambda: load("Sparrow7")) == (0, 1, 0), position
        assert not model_file.exists()  # the damaged entry is removed
        (model_file,) = private_cache.glob("*.mjb")  # the compile stored a whole one again
    assert len(positions) > 60
    service._recent.forget(str(private_cache))
    assert counted(lambda: load("Sparrow7")) == (1, 0, 0)
    assert_same_model(load("Sparrow7"), reference)


def test_a_truncated_manifest_is_a_miss_and_is_removed(private_cache: Path) -> None:
    load("Sparrow7")
    (manifest,) = entries(private_cache)
    manifest.write_text(manifest.read_text()[:50])
    assert counted(lambda: load("Sparrow7")) == (0, 1, 0)
    assert json.loads(manifest.read_text())["label"] == "Sparrow70 + Pedestal0 + PincerGripper0_right"


def test_leftovers_of_a_killed_writer_are_removed_once_old(private_cache: Path) -> None:
    private_cache.mkdir()
    key = "0" * 40
    old_temp, young_temp = private_cache / f".{key}.json.abc.tmp", private_cache / f".{key}.json.def.tmp"
    orphan = private_cache / f"{key}-123456789abc.mjb"
    unrelated = private_cache / "notes.json"  # not the cache's: never removed
    for path in (old_temp, young_temp, orphan, unrelated):
        path.write_bytes(b"\0" * 100)
    hour_ago = time.time() - 3600
    for path in (old_temp, orphan, unrelated):
        os.utime(path, (hour_ago, hour_ago))
    load("Sparrow7")
    assert not old_temp.exists() and not orphan.exists()
    assert young_temp.exists() and unrelated.exists()


WORKER = textwrap.dedent(
    """
    import assembler
    from assembler.compiler.stored import counts  # a hit answered from its record never imports the service
    assembler.assemble("Sparrow7").get_model()
    print(counts.misses + counts.hits)
    """
)


def test_two_processes_filling_one_entry_both_succeed(private_cache: Path) -> None:
    workers = [
        subprocess.Popen(
            [sys.executable, "-c", WORKER], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True
        )
        for _ in range(2)
    ]
    results = [worker.communicate(timeout=120) for worker in workers]
    assert [worker.returncode for worker in workers] == [0, 0], results
    assert [out.strip() for out, _ in results] == ["1", "1"]
    assert len(entries(private_cache)) == 1
    assert_same_model(assembler.assemble("Sparrow7").get_model(), fresh("Sparrow7"))


# ----- the command --------------------------------------------------------------------------


def test_cache_info_and_clear(private_cache: Path, capsys: pytest.CaptureFixture[str]) -> None:
    load("Sparrow7")
    assert main(["cache", "info"]) == 0
    rows = dict(line.split(None, 1) for line in capsys.readouterr().out.splitlines())
    assert rows["location"] == "model-cache" and rows["entries"] == "1" and rows["status"] == "enabled"
    assert rows["limit"] == "2.0 GB (ASSEMBLER_CACHE_MAX_BYTES), every part together"
    (private_cache / "notes.txt").write_text("mine")
    files = sum(1 for path in private_cache.rglob("*") if path.is_file()) - 1  # all but notes.txt
    assert main(["cache", "clear"]) == 0
    assert capsys.readouterr().out.startswith(f"removed {files} files (")  # models, records: every part
    assert [path.name for path in private_cache.rglob("*") if path.is_file()] == ["notes.txt"]
    assert [path.name for path in private_cache.iterdir()] == ["notes.txt"]  # emptied part folders go


def test_a_bad_size_limit_is_one_line_naming_the_variable(
    monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setenv("ASSEMBLER_CACHE_MAX_BYTES", "lots")
    assert main(["cache", "info"]) == 1
    assert capsys.readouterr().err == (
        "ASSEMBLER_CACHE_MAX_BYTES: expected a size such as 2G, 500M or 1048576, got 'lots'\n"
    )


# ----- the benchmark harness ----------------------------------------------------------------


def test_benchmark_quick_run_writes_every_measure(tmp_path: Path) -> None:
    repository = Path(__file__).resolve().parents[2]
    output = tmp_path / "bench"
    command = [sys.executable, "-m", "benchmarks", "--quick", "--robots", "Sparrow7", "--output", str(output)]
    result = subprocess.run(command, cwd=repository, capture_output=True, text=True, timeout=300)
    assert result.returncode == 0, result.stderr[-2000:]
    figures = json.loads((output / "results.json").read_text())["figures"]
    measures = {figure["measure"] for figure in figures}
    assert measures == {"2 warm", "3 start-up", "4 get_xml", "6 repeated load", "6 scale"}
    report = (output / "results.md").read_text()
    assert "| 2 warm | Sparrow7 load_model |" in report and f"MuJoCo {mujoco.__version__}" in report


# ----- files that change between making a robot and compiling it -----------------------------


def test_an_mjcf_edited_after_the_robot_was_made_is_not_stored_under_its_new_content(mesh_arm: Path) -> None:
    robot = assembler.assemble("MeshArm")  # parses meshy.xml now
    edit(
        mesh_arm / "meshy.xml", MESH_ARM_MJCF.replace('size="0.05 0.05"', 'size="0.09 0.05"'), seconds_ago=30
    )
    robot.get_model()  # compiled from what was parsed: the old radius
    wait_for_writes()
    assert load("MeshArm").geom("robot0_base_col").size[0] == pytest.approx(0.09)


def test_an_included_file_edited_between_two_robots_is_read_again(mesh_arm: Path) -> None:
    edit(mesh_arm / "parts.xml", '<mujoco><default><geom rgba="1 0 0 1"/></default></mujoco>', 3600)
    edit(
        mesh_arm / "meshy.xml",
        MESH_ARM_MJCF.replace("<asset>", '<include file="parts.xml"/>\n  <asset>'),
        3600,
    )
    assembler.register_specs(mesh_arm)
    assert load("MeshArm").geom("robot0_link2_col").rgba.tolist() == [
        1.0,
        0.0,
        0.0,
        1.0,
    ]  # the included default's
    edit(mesh_arm / "parts.xml", '<mujoco><default><geom rgba="0 0 1 1" group="1"/></default></mujoco>', 30)
    assert load("MeshArm").geom("robot0_link2_col").rgba.tolist() == [0.0, 0.0, 1.0, 1.0]


def test_the_same_spec_in_another_environment_has_its_own_entry(tmp_path: Path, private_cache: Path) -> None:
    """``package://`` resolves per environment: two installs of a package must not share entries."""
    spec = tmp_path / "fake.yaml"
    spec.write_text("name: FakeBot\nmjcf: package://fakebot/robot.xml\n")
    sizes = []
    for install, radius in (("a", "0.3"), ("b", "0.9")):
        package = tmp_path / install / "fakebot"
        (package / "meshes").mkdir(parents=True)
        (package / "__init__.py").write_text("")
        edit(package / "meshes" / "tet.obj", TETRAHEDRON_OBJ, 3600)
        edit(package / "robot.xml", MESH_ARM_MJCF.replace('size="0.05 0.05"', f'size="{radius} 0.05"'), 3600)
        script = (
            "import sys, assembler, assembler.compiler.service; (cls,) = assembler.register_specs(sys.argv[1]); "
            "m = assembler.assemble(cls.__name__).get_model(); assembler.compiler.service.wait_for_writes(); "
            "print(m.geom('robot0_base_col').size[0])"
        )
        environment = {
            **os.environ,
            "PYTHONPATH": str(tmp_path / install),
            "ASSEMBLER_ALLOW_PATHS": str(tmp_path),
        }
        done = subprocess.run(
            [sys.executable, "-c", script, str(spec)],
            env=environment,
            capture_output=True,
            text=True,
            check=True,
        )
        sizes.append(float(done.stdout.split()[-1]))
    assert sizes == [0.3, 0.9]


LOAD = "import assembler; print(assembler.load_model('Sparrow7').njnt, assembler.assemble('Sparrow7').get_xml()[:7])"


@pytest.mark.parametrize(
    "pattern", ["*.mjb", "*.json", "*.xml", "requests/*.json", "**/*"], ids=lambda p: p.replace("*", "any")
)
def test_a_fifo_in_place_of_a_cache_file_is_a_miss_not_a_wait(pattern: str, private_cache: Path) -> None:
    """Opening a FIFO waits for a writer: a cache file replaced by one would hang every build."""
    environment = {**os.environ, "ASSEMBLER_CACHE_DIR": str(private_cache)}
    run = [sys.executable, "-c", LOAD]
    first = subprocess.run(run, capture_output=True, text=True, env=environment, timeout=300)
    assert first.stdout == "9 <mujoco\n", first.stderr
    replaced = [path for path in private_cache.glob(pattern) if path.is_file()]
    assert replaced
    for path in replaced:
        path.unlink()
        os.mkfifo(path)
    again = subprocess.run(run, capture_output=True, text=True, env=environment, timeout=120)
    assert (again.returncode, again.stdout, again.stderr) == (0, "9 <mujoco\n", "")
