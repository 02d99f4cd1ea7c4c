"""The one door for outputs: ``build -o`` and ``--bundle`` replace only a regular file of their own.

Each row is where the output goes and the one line ``assembler build`` prints; the target is left
exactly as it was (a FIFO stays a FIFO, a link a link, the spec's MJCF its content), and the next
build still works. The same rows run twice: with the model compiled, and answered from the cache
(the request record and its entry), since both paths write through the same writer.
"""

from __future__ import annotations

import os
import stat
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import mujoco
import pytest

from assembler.cli import main
from assembler.compiler.service import wait_for_writes
from assembler.urdf.mesh_formats import importable
from tests.conftest import INCLUDING_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache
from tests.urdf.fixtures import ARM_URDF, write_package

TETRA = TETRAHEDRON_OBJ

ARM_MJCF = INCLUDING_ARM_MJCF
ACTUATORS = '<mujoco><actuator><position name="act1" joint="joint1" kp="50"/></actuator></mujoco>\n'
SPEC = "name: WriteArm\nmjcf: arm.xml\n"

INPUT = "cannot write {path}: it is {path}, an input of this build; writing there would destroy it: choose another path"
LINK = "cannot write out.xml: it is a symbolic link (to {to}); an output replaces only a regular file: remove the link or choose another path"
FOREIGN = "{path} is there and is not a file an earlier bundle wrote (the .assembler-bundle.json there does not name it); a bundle never replaces other files: move it away or choose another folder"


@pytest.fixture(autouse=True)
def arm(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A spec folder (spec, MJCF, an included file, a mesh) as the working folder, with a private cache."""
    use_private_cache(tmp_path / "cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    for name, text in [
        ("arm/arm.yaml", SPEC),
        ("arm/arm.xml", ARM_MJCF),
        ("arm/actuators.xml", ACTUATORS),
        ("arm/meshes/tet.obj", TETRA),
    ]:
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        then = time.time() - 3600  # older than the cache's "just edited" window
        os.utime(path, (then, then))
    yield tmp_path / "arm"
    wait_for_writes()


def build(*flags: str) -> int:
    return main(["build", "arm/arm.yaml", "--no-base", *flags])


def snapshot(path: Path) -> tuple[int, bytes | str]:
    """A target's kind and content (a link's target), to show it was left alone."""
    found = os.lstat(path)
    if stat.S_ISLNK(found.st_mode):
        return stat.S_IFMT(found.st_mode), os.readlink(path)
    if stat.S_ISREG(found.st_mode):
        return stat.S_IFMT(found.st_mode), path.read_bytes()
    return stat.S_IFMT(found.st_mode), b""


def make_fifo(root: Path) -> Path:
    os.mkfifo(root / "out.xml")
    return root / "out.xml"


def make_link_to_file(root: Path) -> Path:
    (root / "precious.txt").write_text("keep me\n")
    (root / "out.xml").symlink_to("precious.txt")
    return root / "out.xml"


def make_dangling_link(root: Path) -> Path:
    (root / "out.xml").symlink_to("nowhere.xml")
    return root / "out.xml"


def make_hard_link_to_mjcf(root: Path) -> Path:
    os.link(root / "arm" / "arm.xml", root / "out.xml")
    return root / "out.xml"


# fmt: off
TARGETS: list[tuple[str, Callable[[Path], Path] | str, str]] = [
    ("fifo", make_fifo, "cannot write out.xml: it is a FIFO (named pipe), not a regular file; an output replaces only a regular file: choose another path"),
    ("link-to-a-file", make_link_to_file, LINK.format(to="precious.txt")),
    ("dangling-link", make_dangling_link, LINK.format(to="nowhere.xml")),
    ("the-spec", "arm/arm.yaml", INPUT.format(path="arm/arm.yaml")),
    ("the-mjcf", "arm/arm.xml", INPUT.format(path="arm/arm.xml")),
    ("an-included-file", "arm/actuators.xml", INPUT.format(path="arm/actuators.xml")),
    ("a-mesh", "arm/meshes/tet.obj", INPUT.format(path="arm/meshes/tet.obj")),
    ("a-hard-link-to-the-mjcf", make_hard_link_to_mjcf, "cannot write out.xml: it is arm/arm.xml, an input of this build; writing there would destroy it: choose another path"),
]
# fmt: on


@pytest.mark.parametrize("cached", [False, True], ids=["compiled", "answered-from-the-cache"])
@pytest.mark.parametrize(("name", "make", "message"), TARGETS, ids=[row[0] for row in TARGETS])
def test_an_output_never_replaces_what_is_not_a_regular_file_of_its_own(
    name: str,
    make: Callable[[Path], Path] | str,
    message: str,
    cached: bool,
    tmp_path: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    if cached:
        assert build("-o", "first.xml") == 0
        wait_for_writes()
    target = make(tmp_path) if callable(make) else tmp_path / make
    before = snapshot(target)
    capsys.readouterr()
    assert build("-o", os.path.relpath(target, tmp_path)) == 1
    assert capsys.readouterr().err == message + "\n"
    assert snapshot(target) == before
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")] == []
    assert build("-o", "again.xml") == 0  # every input is still whole
    assert mujoco.MjModel.from_xml_path("again.xml").nu == 1


def test_a_device_is_never_turned_into_a_file(capsys: pytest.CaptureFixture[str]) -> None:
    assert build("-o", os.devnull) == 1
    assert capsys.readouterr().err == (
        f"cannot write {os.devnull}: it is a character device, not a regular file; an output replaces only "
        "a regular file: choose another path\n"
    )
    assert stat.S_ISCHR(os.lstat(os.devnull).st_mode)


def test_building_onto_its_own_earlier_output_replaces_it(tmp_path: Path) -> None:
    assert build("-o", "arm.xml") == 0
    first = (tmp_path / "arm.xml").read_bytes()
    assert build("-o", "arm.xml", "--set", "joint_defaults.damping=0.5") == 0
    assert (tmp_path / "arm.xml").read_bytes() != first
    assert build("--bundle", "out") == 0
    assert build("--bundle", "out", "--set", "joint_defaults.damping=0.5") == 0
    assert sorted(p.name for p in (tmp_path / "out").rglob("*")) == [
        ".assembler-bundle.json",
        "WriteArm.xml",
        "assets",
        "tet.obj",
    ]


def test_a_bundle_never_replaces_a_file_no_bundle_wrote(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    mine = tmp_path / "out" / "assets" / "tet.obj"
    mine.parent.mkdir(parents=True)
    mine.write_text("my own file\n")
    assert build("--bundle", "out") == 1
    assert capsys.readouterr().err == FOREIGN.format(path="out/assets/tet.obj") + "\n"
    assert mine.read_text() == "my own file\n"
    assert sorted(p.name for p in (tmp_path / "out").rglob("*")) == ["assets", "tet.obj"]  # nothing written


def test_a_bundle_never_replaces_an_xml_no_bundle_wrote(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (tmp_path / "out").mkdir()
    (tmp_path / "out" / "WriteArm.xml").write_text("notes\n")
    assert build("--bundle", "out") == 1
    assert capsys.readouterr().err == FOREIGN.format(path="out/WriteArm.xml") + "\n"
    assert (tmp_path / "out" / "WriteArm.xml").read_text() == "notes\n"


@pytest.mark.skipif(not (importable("trimesh") and importable("collada")), reason="needs the urdf extra")
@pytest.mark.parametrize(
    "target",
    ["ros/my_arm/urdf/my_arm.urdf", "ros/my_arm/meshes/cube.dae"],
    ids=["the-urdf", "its-collada-mesh"],
)
def test_a_urdf_robot_never_writes_over_its_urdf_or_meshes(
    target: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_package(tmp_path / "ros", urdf=ARM_URDF)
    (tmp_path / "urdf_arm.yaml").write_text(
        "name: UrdfArm\nurdf: ros/my_arm/urdf/my_arm.urdf\neef_bodies: {right: tool}\n"
    )
    before = (tmp_path / target).read_bytes()
    capsys.readouterr()
    assert main(["build", "urdf_arm.yaml", "--no-base", "-o", target]) == 1
    assert capsys.readouterr().err == INPUT.format(path=target) + "\n"
    assert (tmp_path / target).read_bytes() == before
