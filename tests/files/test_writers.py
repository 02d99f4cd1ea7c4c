"""Every writer of a user's file goes through the one door (:func:`assembler.files.writing.replace_file`).

The first table runs each command that writes a file with its output pointed at each file it reads
(the spec, the scene or experiment file, the MJCF, an included file, a mesh), a hard link to its
MJCF, a symbolic link, a FIFO and a device: each exits 1 with one line naming the target and what
to do, and leaves the target exactly as it was. The last test reads the package's source so no
module writes a file except through the door (the cache writes inside its own folder).
"""

from __future__ import annotations

import ast
import os
import stat
import time
from collections.abc import Callable, Iterator
from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.compiler.service import wait_for_writes
from assembler.errors import AssemblerError
from assembler.files.inputs import input_at, note_inputs
from assembler.urdf.mesh_formats import importable
from tests.conftest import INCLUDING_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache
from tests.urdf.fixtures import ARM_URDF, write_package

ACTUATORS = '<mujoco><actuator><position name="act1" joint="joint1" kp="50"/></actuator></mujoco>\n'
FILES = {
    "arm/arm.yaml": "name: DoorArm\nmjcf: arm.xml\n",
    "arm/arm.xml": INCLUDING_ARM_MJCF,
    "arm/actuators.xml": ACTUATORS,
    "arm/meshes/tet.obj": TETRAHEDRON_OBJ,
    "scene.yaml": "kind: scene\nname: Door\nrobots:\n  - robot: arm/arm.yaml\n",
    "experiment.yaml": "kind: experiment\nname: Door\nrobots:\n  - robot: arm/arm.yaml\n",
}
ROBOT_FILES = ["arm/arm.yaml", "arm/arm.xml", "arm/actuators.xml", "arm/meshes/tet.obj"]

INPUT = "cannot write {path}: it is {path}, an input of this build; writing there would destroy it: choose another path"
HARD_LINK = "cannot write {path}: it is arm/arm.xml, an input of this build; writing there would destroy it: choose another path"
LINK = "cannot write {path}: it is a symbolic link (to arm/arm.xml); an output replaces only a regular file: remove the link or choose another path"
FIFO = "cannot write {path}: it is a FIFO (named pipe), not a regular file; an output replaces only a regular file: choose another path"
DEVICE = "cannot write {path}: it is a character device, not a regular file; an output replaces only a regular file: choose another path"

# A command's words, with {out} where its output goes, and the files it reads.
COMMANDS: dict[str, tuple[list[str], list[str]]] = {
    "build": (["build", "arm/arm.yaml", "--no-base", "-o", "{out}"], ROBOT_FILES),
    "new": (["new", "arm/arm.xml", "--force", "-o", "{out}"], ROBOT_FILES[1:]),
    "scene": (["scene", "scene.yaml", "-o", "{out}"], ["scene.yaml", *ROBOT_FILES]),
    "experiment": (["experiment", "experiment.yaml", "-o", "{out}"], ["experiment.yaml", *ROBOT_FILES]),
    "render": (["render", "arm/arm.yaml", "--no-base", "--size", "32x24", "-o", "{out}"], ROBOT_FILES),
}


@pytest.fixture(autouse=True)
def folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """The files the commands read, in the working folder, with a private cache."""
    use_private_cache(tmp_path / "cache", monkeypatch)
    monkeypatch.chdir(tmp_path)
    then = time.time() - 3600  # older than the cache's "just edited" window
    for name, text in FILES.items():
        path = tmp_path / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_text(text)
        os.utime(path, (then, then))
    yield tmp_path
    wait_for_writes()


def _hard_link(root: Path, name: str) -> None:
    os.link(root / "arm" / "arm.xml", root / name)


def _link(root: Path, name: str) -> None:
    (root / name).symlink_to("arm/arm.xml")


def _fifo(root: Path, name: str) -> None:
    os.mkfifo(root / name)


TARGETS: list[tuple[str, Callable[[Path, str], None] | None, str]] = [
    ("a-hard-link-to-the-mjcf", _hard_link, HARD_LINK),
    ("a-symbolic-link", _link, LINK),
    ("a-fifo", _fifo, FIFO),
]


def _cases() -> list[object]:
    cases: list[object] = []
    for command, (_, inputs) in COMMANDS.items():
        for path in inputs:
            cases.append(pytest.param(command, path, None, INPUT, id=f"{command}-over-{path}"))
        for name, make, message in TARGETS:
            cases.append(pytest.param(command, "out.xml", make, message, id=f"{command}-over-{name}"))
        cases.append(pytest.param(command, os.devnull, None, DEVICE, id=f"{command}-over-a-device"))
    return cases


def _snapshot(path: Path) -> tuple[int, bytes | str]:
    found = os.lstat(path)
    if stat.S_ISLNK(found.st_mode):
        return stat.S_IFMT(found.st_mode), os.readlink(path)
    if stat.S_ISREG(found.st_mode):
        return stat.S_IFMT(found.st_mode), path.read_bytes()
    return stat.S_IFMT(found.st_mode), b""


@pytest.mark.parametrize(("command", "target", "make", "message"), _cases())
def test_no_command_writes_over_its_inputs_links_fifos_or_devices(
    command: str,
    target: str,
    make: Callable[[Path, str], None] | None,
    message: str,
    folder: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    if make is not None:
        make(folder, target)
    before = {name: (folder / name).read_bytes() for name in FILES}
    kept = _snapshot(folder / target)
    words, _ = COMMANDS[command]
    assert main([word.format(out=target) for word in words]) == 1
    assert capsys.readouterr().err == message.format(path=target) + "\n"
    assert _snapshot(folder / target) == kept
    assert {name: (folder / name).read_bytes() for name in FILES} == before
    assert [p.name for p in folder.rglob("*.tmp") if p.parts[len(folder.parts)] != "cache"] == []


@pytest.mark.parametrize(("name", "make", "message"), TARGETS, ids=[row[0] for row in TARGETS])
def test_variants_never_write_a_variant_over_a_link_or_fifo(
    name: str,
    make: Callable[[Path, str], None],
    message: str,
    folder: Path,
    capsys: pytest.CaptureFixture[str],
) -> None:
    (folder / "out").mkdir()
    make(folder, "out/DoorArm_0000.xml")
    if make is _link:  # a link's target is taken relative to its own folder
        (folder / "out/DoorArm_0000.xml").unlink()
        (folder / "out/DoorArm_0000.xml").symlink_to("arm/arm.xml")
    kept = _snapshot(folder / "out/DoorArm_0000.xml")
    mjcf = (folder / "arm/arm.xml").read_bytes()
    code = main(
        ["variants", "arm/arm.yaml", "--no-base", "--grid", "joint_defaults.damping=0.1,0.2", "-o", "out"]
    )
    assert code == 1
    assert capsys.readouterr().err == message.format(path="out/DoorArm_0000.xml") + "\n"
    assert _snapshot(folder / "out/DoorArm_0000.xml") == kept
    assert (folder / "arm/arm.xml").read_bytes() == mjcf


@pytest.mark.parametrize("target", ROBOT_FILES)
def test_robot_model_save_never_writes_over_its_inputs(target: str, folder: Path) -> None:
    assembler.register_specs(folder / "arm")
    robot = assembler.assemble("DoorArm", base=None)
    before = (folder / target).read_bytes()
    with pytest.raises(
        AssemblerError, match=f"^cannot write {target}: it is {target}, an input of this build"
    ):
        robot.save(target)
    assert (folder / target).read_bytes() == before


def test_a_bundle_never_writes_over_an_input_through_a_link(
    folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    (folder / "out").mkdir()
    os.link(folder / "arm/arm.xml", folder / "out/DoorArm.xml")
    assert main(["build", "arm/arm.yaml", "--no-base", "--bundle", "out"]) == 1
    assert capsys.readouterr().err == HARD_LINK.format(path="out/DoorArm.xml") + "\n"
    assert (folder / "arm/arm.xml").read_text() == INCLUDING_ARM_MJCF


# What may write a file by itself, and why; everything else writes through files/writing.py.
WRITERS_OF_THEIR_OWN = {
    "assembler/files/writing.py": "the door",
    "assembler/cli/endings.py": "opens os.devnull for the process's streams",
    "assembler/urdf/mesh_formats.py": "fills the cache's temporary file of a converted mesh (cache/content.kept_file)",
}
"""Modules under ``assembler/cache/`` write inside the cache folder, which is theirs."""

WRITING_CALLS = {
    "rename", "mkstemp", "NamedTemporaryFile", "write_text", "write_bytes", "touch", "symlink_to",
    "hardlink_to", "export", "savez", "tofile", "mj_saveLastXML", "mj_saveModel", "to_file",
}  # fmt: skip
"""Calls that create or replace a file; ``os`` and ``shutil`` ones are matched with their module
(``str.replace`` and ``array.copy`` write nothing)."""

OS_WRITING_CALLS = {"replace", "rename", "link", "symlink", "copy", "copy2", "copyfile", "copyfileobj", "move"}  # fmt: skip


def _writes(node: ast.Call) -> bool:
    func = node.func
    name = func.attr if isinstance(func, ast.Attribute) else func.id if isinstance(func, ast.Name) else ""
    owner = func.value.id if isinstance(func, ast.Attribute) and isinstance(func.value, ast.Name) else ""
    if name in WRITING_CALLS or (owner in ("os", "shutil") and name in OS_WRITING_CALLS):
        return True
    if owner == "os" and name == "open":
        flags = ast.unparse(node.args[1]) if len(node.args) > 1 else ""
        return any(flag in flags for flag in ("O_WRONLY", "O_RDWR", "O_CREAT"))
    if name in ("open", "fdopen"):  # open(path, "w"), os.fdopen(fd, "w"), path.open("w")
        modes = [*node.args[:2], *(k.value for k in node.keywords if k.arg == "mode")]
        return any(
            isinstance(m, ast.Constant)
            and isinstance(m.value, str)
            and set(m.value) <= set("rwxabt+")
            and bool(set(m.value) & set("wax+"))
            for m in modes
        )
    return False


def test_no_module_writes_a_file_except_through_the_door() -> None:
    package = Path(assembler.__file__).parent
    found = []
    for path in sorted(package.rglob("*.py")):
        relative = path.relative_to(package.parent).as_posix()
        if relative.startswith("assembler/cache/") or relative in WRITERS_OF_THEIR_OWN:
            continue
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.Call) and _writes(node):
                found.append(f"{relative}:{node.lineno}: {ast.unparse(node)[:80]}")
    assert found == []


@pytest.mark.skipif(not (importable("trimesh") and importable("collada")), reason="needs the urdf extra")
@pytest.mark.parametrize(
    "target",
    ["ros/my_arm/urdf/my_arm.urdf", "ros/my_arm/meshes/cube.stl", "ros/my_arm/meshes/cube.dae"],
    ids=["the-urdf", "its-stl-mesh", "its-collada-mesh"],
)
def test_new_never_writes_over_the_urdf_or_meshes_it_read(
    target: str, folder: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    write_package(folder / "ros", urdf=ARM_URDF)
    before = (folder / target).read_bytes()
    assert main(["new", "ros/my_arm/urdf/my_arm.urdf", "--force", "-o", target]) == 1
    assert capsys.readouterr().err == INPUT.format(path=target) + "\n"
    assert (folder / target).read_bytes() == before


def test_an_input_is_known_by_its_inode_while_it_is_there_under_its_name(folder: Path) -> None:
    """A hard link is the input; an inode the input left behind (deleted, its number given to a new
    file) is not: a long process or a test session must not refuse an unrelated file."""
    read, link = folder / "read.xml", folder / "link.xml"
    read.write_text("<mujoco/>\n")
    note_inputs([read])
    os.link(read, link)
    assert input_at(link) == str(read)
    read.unlink()
    assert input_at(link) is None
