"""Emitted MJCF: compiles from any folder, byte-identical for equal inputs, written atomically."""

from __future__ import annotations

import os
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import MjcfError
from assembler.files.writing import write_atomically
from tests.conftest import TETRAHEDRON_OBJ

MESH_ROBOT = """\
<mujoco model="meshy">
  <compiler meshdir="meshes" texturedir="textures"/>
  <asset>
    <mesh name="tetra" file="tetra.obj"/>
    <mesh name="tetra_small" file="sub/tetra.obj" scale="0.5 0.5 0.5"/>
    <texture name="grid" type="2d" file="grid.png"/>
    <material name="grid" texture="grid"/>
  </asset>
  <worldbody>
    <body name="base">
      <joint name="spin" axis="0 0 1"/>
      <geom type="mesh" mesh="tetra" material="grid" group="1"/>
      <geom type="mesh" mesh="tetra_small" pos="0 0 0.2"/>
    </body>
  </worldbody>
</mujoco>
"""

TETRA_BIG = TETRAHEDRON_OBJ.replace("0.1", "0.2")


def _png(path: Path) -> None:
    """A real 2x2 PNG, written with MuJoCo's own renderer-free tools: raw zlib + headers."""
    import struct
    import zlib

    rows = b"".join(b"\x00" + bytes([200, 200, 200] * 2) for _ in range(2))

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (
            struct.pack(">I", len(data))
            + kind
            + data
            + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF)
        )

    png = b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", 2, 2, 8, 2, 0, 0, 0))
    png += chunk(b"IDAT", zlib.compress(rows)) + chunk(b"IEND", b"")
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(png)


@pytest.fixture
def meshy(write) -> type[assembler.RobotModel]:  # type: ignore[no-untyped-def]
    write("robot/meshes/tetra.obj", TETRAHEDRON_OBJ)
    write("robot/meshes/sub/tetra.obj", TETRA_BIG)
    _png(Path(write("robot/textures/.keep", "")).parent / "grid.png")
    write("robot/meshy.xml", MESH_ROBOT)
    (cls,) = assembler.register_specs(write("robot/meshy.yaml", "name: Meshy\nmjcf: meshy.xml\n"))
    return cls


def test_emitted_xml_loads_from_any_working_directory(meshy, tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    out = meshy(idn=0).save(tmp_path / "out" / "meshy.xml")
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    monkeypatch.chdir(elsewhere)
    model = mujoco.MjModel.from_xml_path(str(out))
    assert model.nmesh == 2 and model.ntex == 1


def test_same_inputs_give_byte_identical_output(meshy, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    first = meshy(idn=0).save(tmp_path / "a.xml").read_bytes()
    second = meshy(idn=0).save(tmp_path / "b.xml").read_bytes()
    assert first == second


def test_bundle_copies_assets_and_uses_relative_paths(meshy, tmp_path: Path, monkeypatch) -> None:  # type: ignore[no-untyped-def]
    from assembler.mjcf.emit import bundle

    robot = meshy(idn=0)
    robot.get_model()
    target = bundle(robot.mjspec, tmp_path / "bundle", "meshy.xml")
    files = sorted(p.name for p in (tmp_path / "bundle" / "assets").iterdir())
    assert files == ["grid.png", "tetra.obj", "tetra_1.obj"]  # two different tetra.obj files
    text = target.read_text()
    assert str(tmp_path / "robot") not in text
    moved = tmp_path / "moved"
    (tmp_path / "bundle").rename(moved)
    monkeypatch.chdir(tmp_path)
    model = mujoco.MjModel.from_xml_path(str(moved / "meshy.xml"))
    original = robot.get_model()
    np.testing.assert_allclose(model.mesh_vert, original.mesh_vert)


def test_missing_mesh_is_named_before_anything_is_written(write, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    write("robot/meshy.xml", MESH_ROBOT)
    (cls,) = assembler.register_specs(write("robot/meshy.yaml", "name: Meshy\nmjcf: meshy.xml\n"))
    with pytest.raises(
        MjcfError,
        match=r"meshy.yaml:2:7: mjcf: .*meshy.xml: asset file not found: .*meshes/tetra.obj$",
    ):
        cls(idn=0).check()


def test_a_failed_write_keeps_the_old_file_and_leaves_no_temporary(tmp_path: Path) -> None:
    target = tmp_path / "robot.xml"
    target.write_text("old content")

    class Exploding(str):
        def encode(self, *args: object, **kwargs: object) -> bytes:  # type: ignore[override]
            raise OSError("disk full")

    with pytest.raises(OSError, match="disk full"):
        write_atomically(target, Exploding("new"))
    assert target.read_text() == "old content"
    assert os.listdir(tmp_path) == ["robot.xml"]


def test_a_robot_that_does_not_compile_writes_nothing(write, tmp_path: Path) -> None:  # type: ignore[no-untyped-def]
    write(
        "s/massless.xml",
        "<mujoco><worldbody><body name='b'><joint name='j'/></body></worldbody></mujoco>",
    )
    (cls,) = assembler.register_specs(write("s/robot.yaml", "name: Massless\nmjcf: massless.xml\n"))
    target = tmp_path / "out.xml"
    target.write_text("previous build")
    with pytest.raises(MjcfError):
        cls(idn=0).save(target)
    assert target.read_text() == "previous build"


def test_written_files_get_the_usual_permissions_and_overwrites_keep_theirs(tmp_path: Path) -> None:

    fresh, kept = tmp_path / "fresh.xml", tmp_path / "kept.xml"
    kept.write_text("old")
    kept.chmod(0o640)
    umask = os.umask(0o022)
    try:
        write_atomically(fresh, "<mujoco/>")
        write_atomically(kept, "<mujoco/>")
    finally:
        os.umask(umask)
    assert fresh.stat().st_mode & 0o777 == 0o644
    assert kept.stat().st_mode & 0o777 == 0o640 and kept.read_text() == "<mujoco/>"
