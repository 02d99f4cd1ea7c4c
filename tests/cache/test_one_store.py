"""The one store: nothing stale is served and nothing unverified, one bound, one clear, one info.

Each stale case is run as a user meets it, in new processes (``assembler build -o``), and the
answer is compared with a build in an empty cache: a file edited with its size and time kept
(``touch -r``), a symbolic link re-pointed (a mesh's own or its folder's), an edited converted mesh
or robosuite part file in the cache, the package variables switched. ``--no-cache`` reads nothing
from the cache, and a written model does not depend on the cache folder.
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import time
from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler import cache
from assembler.cache.content import CONVERTED, PARTS, content_folder
from assembler.cache.content import kept_file as kept_content
from assembler.cache.folder import evict
from assembler.cli import main
from assembler.compiler import service
from assembler.compiler.service import wait_for_writes
from assembler.robosuite.files import kept_file, written_file
from assembler.urdf.mesh_formats import converted_dir, importable
from assembler.urdf.packages import package_folders
from tests.conftest import INCLUDING_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache
from tests.urdf.fixtures import ARM_URDF, write_package, write_stl

ASSEMBLER = [str(Path(sys.executable).parent / "assembler")]

TETRA = TETRAHEDRON_OBJ.replace("v 0 0 0.1", "v 0 0 {z}")  # its height as a parameter
ARM_MJCF = INCLUDING_ARM_MJCF
ACTUATORS = '<mujoco><actuator><position name="act1" joint="joint1" kp="{kp}"/></actuator></mujoco>\n'
NEEDS_CONVERTER = pytest.mark.skipif(
    not (importable("trimesh") and importable("collada")), reason="needs the urdf extra (trimesh, pycollada)"
)


def backdate(*paths: Path) -> None:
    then = time.time() - 3600  # older than the cache's "just edited" window
    for path in paths:
        os.utime(path, (then, then), follow_symlinks=False)


@pytest.fixture
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A working folder with a spec, its MJCF, an include and a mesh (in ``meshes/``), and a private cache."""
    use_private_cache(tmp_path / "cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    for name, text in [
        ("arm.yaml", "name: StoreArm\nmjcf: arm.xml\n"),
        ("arm.xml", ARM_MJCF),
        ("actuators.xml", ACTUATORS.format(kp=50)),
        ("meshes/tet.obj", TETRA.format(z=0.1)),
    ]:
        (tmp_path / name).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / name).write_text(text)
        backdate(tmp_path / name)
    yield tmp_path
    wait_for_writes()


def build(folder: Path, output: str, *flags: str, env: dict[str, str] | None = None) -> mujoco.MjModel:
    """``assembler build arm.yaml -o output`` in a new process; the model it wrote."""
    done = subprocess.run(
        [*ASSEMBLER, "build", "arm.yaml", "--no-base", "-o", output, *flags],
        cwd=folder,
        capture_output=True,
        text=True,
        env={**os.environ, **(env or {})},
        check=False,
    )
    assert done.returncode == 0 and done.stderr.splitlines()[-1].startswith(f"wrote {output}"), done.stderr
    return mujoco.MjModel.from_xml_path(str(folder / output))


LOAD = """
import json, sys
import assembler
robot = assembler.create_robot(assembler.register_specs(sys.argv[1])[0].__name__)
model = robot.get_model(cache=sys.argv[2] == "cache")
print(json.dumps({name: getattr(model, name).tolist() for name in sys.argv[3:]}))
"""
FIELDS = ("mesh_vert", "actuator_gainprm", "jnt_range", "body_mass")


def compiled(folder: Path, cache: bool = True) -> dict[str, object]:
    """The robot's compiled model (``get_model``, from the cache when ``cache``) in a new process."""
    done = subprocess.run(
        [sys.executable, "-c", LOAD, "arm.yaml", "cache" if cache else "no", *FIELDS],
        cwd=folder,
        capture_output=True,
        text=True,
        check=True,
    )
    return dict(json.loads(done.stdout))


def same(ours: mujoco.MjModel, reference: mujoco.MjModel) -> bool:
    fields = ("mesh_vert", "actuator_gainprm", "body_mass", "body_inertia", "jnt_range")
    return all(np.array_equal(getattr(ours, f), getattr(reference, f)) for f in fields)


def edit_keeping_size_and_times(path: Path, old: str, new: str) -> None:
    """``touch -r``: the content changes, its size and modification time do not."""
    assert len(old) == len(new)
    before = path.stat()
    path.write_text(path.read_text().replace(old, new))
    os.utime(path, ns=(before.st_atime_ns, before.st_mtime_ns))
    assert (path.stat().st_size, path.stat().st_mtime_ns) == (before.st_size, before.st_mtime_ns)


@pytest.mark.parametrize(
    ("file", "old", "new"),
    [
        ("arm.xml", 'range="-3 3"', 'range="-2 2"'),
        ("actuators.xml", 'kp="50"', 'kp="70"'),
        ("meshes/tet.obj", "v 0 0 0.1", "v 0 0 0.3"),
    ],
    ids=["the-mjcf", "an-included-file", "a-mesh"],
)
def test_a_file_edited_with_its_size_and_time_kept_is_not_served_stale(
    folder: Path, file: str, old: str, new: str
) -> None:
    first = compiled(folder)
    assert compiled(folder) == first  # answered from the cache
    edit_keeping_size_and_times(folder / file, old, new)
    after = compiled(folder)
    assert after != first
    assert after == compiled(folder, cache=False)


def test_a_re_pointed_symlinked_mesh_is_a_miss(folder: Path) -> None:
    for name, z in (("one.obj", 0.1), ("two.obj", 0.3)):
        (folder / name).write_text(TETRA.format(z=z))
        backdate(folder / name)
    (folder / "meshes" / "tet.obj").unlink()
    (folder / "meshes" / "tet.obj").symlink_to(folder / "one.obj")
    first = compiled(folder)
    (folder / "meshes" / "tet.obj").unlink()
    (folder / "meshes" / "tet.obj").symlink_to(folder / "two.obj")
    backdate(folder / "meshes" / "tet.obj")
    after = compiled(folder)
    assert after != first
    assert after == compiled(folder, cache=False)


def test_a_re_pointed_symlinked_asset_folder_is_a_miss(folder: Path) -> None:
    for copy, z in (("copy-a", 0.1), ("copy-b", 0.3)):
        (folder / copy).mkdir()
        (folder / copy / "tet.obj").write_text(TETRA.format(z=z))
        backdate(folder / copy / "tet.obj")
    shutil.rmtree(folder / "meshes")
    (folder / "meshes").symlink_to("copy-a")
    first = compiled(folder)
    (folder / "meshes").unlink()
    (folder / "meshes").symlink_to("copy-b")
    after = compiled(folder)
    assert after != first
    assert after == compiled(folder, cache=False)


def test_switching_the_package_variables_is_a_miss(folder: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    assembler.register_specs(folder / "arm.yaml")
    for variable in ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH"):
        before = (service.counts.hits, service.counts.misses)
        monkeypatch.setenv(variable, str(folder / "one"))
        assembler.create_robot("StoreArm").get_model()
        wait_for_writes()
        assembler.create_robot("StoreArm").get_model()
        monkeypatch.setenv(variable, str(folder / "two"))
        assembler.create_robot("StoreArm").get_model()
        assert (service.counts.hits - before[0], service.counts.misses - before[1]) == (1, 2), variable


def test_an_edited_robosuite_part_file_is_written_again(folder: Path) -> None:
    text = '<mujoco model="part"><default><joint damping="0.5"/></default></mujoco>\n'
    path = Path(written_file(text))
    assert path.parent == folder / "cache" / PARTS
    stamp = path.stat().st_mtime_ns
    assert Path(written_file(text)).stat().st_mtime_ns == stamp  # a warm use writes nothing
    path.write_text(text.replace("0.5", "9.5"))
    assert Path(written_file(text)).read_text() == text


def test_a_robosuite_part_file_with_the_cache_off_is_not_in_the_cache(
    folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ASSEMBLER_NO_CACHE", "1")
    path = Path(written_file("<mujoco/>\n"))
    assert not path.is_relative_to(folder / "cache") and path.read_text() == "<mujoco/>\n"
    assert content_folder(PARTS) == path.parent


@pytest.fixture
def urdf_arm(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A URDF robot with a COLLADA mesh (converted to OBJ in the cache), in the working folder."""
    use_private_cache(tmp_path / "cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    package = write_package(tmp_path / "ros", urdf=ARM_URDF)
    backdate(*(path for path in (tmp_path / "ros").rglob("*") if path.is_file()))
    (tmp_path / "arm.yaml").write_text(
        "name: DaeArm\nurdf: ros/my_arm/urdf/my_arm.urdf\neef_bodies: {right: tool}\n"
    )
    backdate(tmp_path / "arm.yaml")  # a spec edited seconds ago gets no request record
    yield package
    wait_for_writes()


@NEEDS_CONVERTER
def test_an_edited_converted_mesh_is_converted_again(urdf_arm: Path, tmp_path: Path) -> None:
    first = build(tmp_path, "first.xml")
    (converted,) = (tmp_path / "cache" / "converted-meshes").glob("cube-*.obj")
    converted.write_text(TETRA.format(z=5.0))
    backdate(converted)
    after = build(tmp_path, "after.xml")
    assert same(after, first)
    assert "v 0 0 5.0" not in "".join(p.read_text() for p in converted.parent.glob("cube-*.obj"))


@NEEDS_CONVERTER
def test_no_cache_reads_nothing_from_the_cache(urdf_arm: Path, tmp_path: Path) -> None:
    first = build(tmp_path, "first.xml")
    (converted,) = (tmp_path / "cache" / "converted-meshes").glob("cube-*.obj")
    converted.write_text(TETRA.format(z=5.0))
    for _ in range(200):  # the first build's background process decodes its meshes into the store
        if list((tmp_path / "cache" / "meshes").glob("*.msh")):
            break
        time.sleep(0.1)
    before = sorted((p.name, p.stat().st_mtime_ns) for p in (tmp_path / "cache").rglob("*"))
    fresh = build(tmp_path, "fresh.xml", "--no-cache")
    assert same(fresh, first)
    assert sorted((p.name, p.stat().st_mtime_ns) for p in (tmp_path / "cache").rglob("*")) == before


@NEEDS_CONVERTER
def test_a_written_model_still_loads_after_the_cache_is_removed(urdf_arm: Path, tmp_path: Path) -> None:
    build(tmp_path, "arm.xml")
    shutil.rmtree(tmp_path / "cache")
    model = mujoco.MjModel.from_xml_path(str(tmp_path / "arm.xml"))
    assert (
        model.nmesh > 0
        and sorted(p.name for p in (tmp_path / "arm.xml-assets").iterdir())[0] == ".assembler-bundle.json"
    )


@NEEDS_CONVERTER
def test_a_model_saved_from_python_still_loads_after_the_cache_is_removed(
    urdf_arm: Path, tmp_path: Path
) -> None:
    assembler.register_specs("arm.yaml")
    saved = assembler.assemble("DaeArm", base=None).save(tmp_path / "saved.xml")
    shutil.rmtree(tmp_path / "cache")
    assert mujoco.MjModel.from_xml_path(str(saved)).nmesh > 0
    assert (tmp_path / "saved.xml-assets").is_dir()


SAVED_IN_A_NEW_PROCESS = (
    "import sys, assembler, assembler.compiler.service; "
    "robot = assembler.assemble('UR5'); robot.save(sys.argv[1]); "
    "assembler.compiler.service.wait_for_writes(); print(type(robot).__name__)"
)


@NEEDS_CONVERTER
@pytest.mark.skipif(not package_folders("example-robot-data"), reason="needs the urdf extra's robots")
def test_a_model_saved_by_a_robot_asked_for_before_still_loads_after_the_cache_is_removed(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    use_private_cache(tmp_path / "cache", monkeypatch)
    answered_by = []
    for attempt in range(4):  # converted meshes too recent to record, then the record, then its answer
        if answered_by[-1:] == ["DeferredRobot"]:
            break
        time.sleep(2.5 if attempt else 0)  # files younger than 2 s are not recorded (file_state.settled)
        done = subprocess.run(
            [sys.executable, "-c", SAVED_IN_A_NEW_PROCESS, str(tmp_path / f"ur5_{attempt}.xml")],
            capture_output=True,
            text=True,
            check=True,
        )
        answered_by.append(done.stdout.split()[-1])
    assert answered_by[-1] == "DeferredRobot"  # a robot asked for before, answered from its record
    saved = tmp_path / f"ur5_{len(answered_by) - 1}.xml"
    shutil.rmtree(tmp_path / "cache")
    assert mujoco.MjModel.from_xml_path(str(saved)).nmesh > 0


@NEEDS_CONVERTER
def test_the_bound_clear_and_info_count_every_part(
    urdf_arm: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(["build", "arm.yaml", "--no-base", "-o", "arm.xml"]) == 0
    backdate(*converted_dir().iterdir())  # converted just now: too recent for a model to be stored
    assert main(["build", "arm.yaml", "--no-base", "-o", "arm.xml"]) == 0
    wait_for_writes()
    written_file("<mujoco/>\n")
    capsys.readouterr()
    assert main(["cache", "info"]) == 0
    rows = dict(line.split("  ", 1) for line in capsys.readouterr().out.splitlines())
    for part in ("models", "decoded meshes", "request records", "converted meshes", "robosuite part files"):
        assert not rows[part].strip().startswith("0 files"), part
    stale = converted_dir() / f"old-{'0' * 32}.obj"
    stale.write_bytes(b"x" * 4_000_000)  # an old conversion: the least recently used part
    backdate(stale)
    total = sum(p.stat().st_size for p in (tmp_path / "cache").rglob("*") if p.is_file())
    monkeypatch.setenv("ASSEMBLER_CACHE_MAX_BYTES", str(total - 1_000_000))
    # a build that stores a model: a structural override (a variant of values only is patched from the
    # cached robot and stores nothing but its request record)
    assert main(["build", "arm.yaml", "--no-base", "-o", "arm.xml", "--set", "remove_free_joint=true"]) == 0
    wait_for_writes()
    assert not stale.exists()
    assert sum(p.stat().st_size for p in (tmp_path / "cache").rglob("*") if p.is_file()) <= total - 1_000_000
    capsys.readouterr()
    assert main(["cache", "clear"]) == 0
    assert [p for p in (tmp_path / "cache").rglob("*") if p.is_file()] == []


def test_a_converted_mesh_in_use_outlives_older_unused_files_and_keeps_its_modification_time(
    folder: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    converted = content_folder(CONVERTED)
    made = [
        kept_content(converted, name, ".obj", lambda path: Path(path).write_bytes(b"v 0 0 0\n" * 5000))
        for name in ("used", "unused")
    ]
    backdate(made[1])
    then = time.time() - 7200
    os.utime(made[0], (then, then))  # made before the other; used now, by a build about to read it
    stamp = made[0].stat().st_mtime_ns
    assert kept_content(converted, "used", ".obj", lambda path: None) == made[0]
    assert (
        made[0].stat().st_mtime_ns == stamp
    )  # still the time it was made: the models made from it stay valid
    evict(folder / "cache", made[0].stat().st_size + 100)
    assert made[0].is_file() and not made[1].exists()


def test_a_converted_mesh_handed_out_in_the_last_minute_is_not_evicted_even_over_the_bound(
    folder: Path,
) -> None:
    """A bound smaller than what builds have in hand (the fuzz tests' 50M, a GR1 entry alone is 44 MB)
    must not take a converted mesh from under the build MuJoCo is about to read it for."""
    converted = content_folder(CONVERTED)
    old, used = (
        kept_content(converted, name, ".obj", lambda path: Path(path).write_bytes(b"v 0 0 0\n" * 5000))
        for name in ("old", "used")
    )
    backdate(old, used)  # both made an hour ago; then one is handed to a build
    assert kept_content(converted, "used", ".obj", lambda path: None) == used
    evict(folder / "cache", 1)
    assert used.is_file() and not old.exists()


def test_a_kept_part_file_is_served_without_emitting_while_its_files_are_unchanged(folder: Path) -> None:
    emitted: list[str] = []

    def emit() -> str:
        text = f'<mujoco model="part">{(folder / "arm.xml").read_text()[:40]!r}</mujoco>\n'
        emitted.append(text)
        return text

    inputs = cache.PartInputs("robot", ("StoreArm",), "{}", str(folder / "arm.xml"), "0")
    path = Path(kept_file(inputs, [str(folder / "arm.xml")], emit))
    assert path.parent == folder / "cache" / PARTS and len(emitted) == 1
    stamp = path.stat().st_mtime_ns
    assert Path(kept_file(inputs, [str(folder / "arm.xml")], emit)) == path and len(emitted) == 1
    assert path.stat().st_mtime_ns == stamp  # a warm use emits and writes nothing
    path.write_text(path.read_text().replace("part", "edit"))  # the part file edited in the cache
    assert Path(kept_file(inputs, [str(folder / "arm.xml")], emit)).read_text() == emitted[0]
    assert len(emitted) == 2
    edit_keeping_size_and_times(folder / "arm.xml", '"arm"', '"ARM"')  # its MJCF edited, touch -r
    assert "ARM" in Path(kept_file(inputs, [str(folder / "arm.xml")], emit)).read_text()
    assert len(emitted) == 3


MESH_URDF = """<robot name="pkg_arm">
  <link name="base"><collision><geometry><mesh filename="package://my_arm/meshes/cube.stl"/></geometry>
  </collision></link>
  <link name="tool"><inertial><mass value="1"/><inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/>
  </inertial></link>
  <joint name="j1" type="revolute"><parent link="base"/><child link="tool"/><axis xyz="0 0 1"/>
    <limit lower="-1" upper="1" effort="1" velocity="1"/></joint>
</robot>
"""


def test_switching_ros_package_path_within_a_process_reads_the_other_copy(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    """A notebook that points ROS_PACKAGE_PATH at another copy of a package gets that copy's meshes,
    and with it unset the package is not found: the URDF read before is not reused for either."""
    use_private_cache(tmp_path / "cache", monkeypatch)
    monkeypatch.delenv("ROS_PACKAGE_PATH", raising=False)
    write_package(tmp_path / "one", urdf=MESH_URDF, declare=False)
    write_stl(
        write_package(tmp_path / "two", urdf=MESH_URDF, declare=False).parents[1] / "meshes/cube.stl", 0.3
    )
    (tmp_path / "arm.yaml").write_text(
        "name: PkgArm\nurdf: one/my_arm/urdf/my_arm.urdf\neef_bodies: {right: tool}\n"
    )
    assembler.register_specs(tmp_path / "arm.yaml")
    extents = []
    for copy in ("one", "two", "one"):
        monkeypatch.setenv("ROS_PACKAGE_PATH", str(tmp_path / copy))
        model = assembler.create_robot("PkgArm").get_model()
        extents.append(round(float(np.ptp(model.mesh_vert[:, 0])), 3))
    assert extents == [0.1, 0.3, 0.1]
    monkeypatch.delenv("ROS_PACKAGE_PATH")
    with pytest.raises(assembler.AssemblerError, match="package 'my_arm' not found"):
        assembler.create_robot("PkgArm").get_model()
