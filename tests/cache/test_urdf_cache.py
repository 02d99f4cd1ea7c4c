"""A URDF robot through the compiled-model cache: its key names the URDF file, and every file its
compile reads (the URDF, its meshes, the OBJ converted from a COLLADA mesh) is a dependency of
the entry, so an edit or a removed conversion is a miss and never a stale model."""

from __future__ import annotations

import os
import subprocess
import sys
import time
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.compiler import service
from assembler.compiler.service import wait_for_writes
from assembler.urdf.mesh_formats import converted_dir, converter_available, importable
from tests.conftest import MESH_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache
from tests.urdf.fixtures import ARM_URDF, write_package, write_stl

SPEC = "name: CachedArm\nurdf: ros/my_arm/urdf/my_arm.urdf\neef_bodies: {right: tool}\n"


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """A fresh cache folder (and converted-mesh folder below it) per test."""
    return use_private_cache(tmp_path / "model-cache", monkeypatch)


def _backdate(*paths: Path, seconds_ago: float = 3600) -> None:
    """As if written a while ago: the cache stores no model made from files modified seconds ago
    (and MuJoCo's own asset cache tells two versions of a file apart by their time in seconds)."""
    then = time.time() - seconds_ago
    for path in paths:
        os.utime(path, (then, then))


def _arm(tmp_path: Path, urdf: str) -> Path:
    package = write_package(tmp_path / "ros", urdf=urdf)
    folder = package.parent.parent
    _backdate(package, folder / "meshes" / "cube.stl", folder / "meshes" / "cube.dae")
    (tmp_path / "arm.yaml").write_text(SPEC)
    assembler.register_specs(tmp_path / "arm.yaml")
    return package


def _load() -> mujoco.MjModel:
    model = assembler.create_robot("CachedArm", idn=0).get_model()
    wait_for_writes()
    return model


def _counted(action: Callable[[], object]) -> tuple[int, int]:
    """(hits, misses) that ``action`` caused."""
    before = (service.counts.hits, service.counts.misses)
    action()
    return service.counts.hits - before[0], service.counts.misses - before[1]


STL_ONLY = ARM_URDF.replace("cube.dae", "cube.stl")
"""The test arm with an STL in place of its COLLADA mesh: nothing to convert (no urdf extra needed)."""


def test_a_urdf_robot_hits_and_editing_a_mesh_or_the_urdf_is_a_miss(tmp_path: Path) -> None:
    urdf = _arm(tmp_path, STL_ONLY)
    assert _counted(_load) == (0, 1)
    assert _counted(_load) == (1, 0)
    write_stl(urdf.parent.parent / "meshes" / "cube.stl", edge=0.2)
    _backdate(urdf.parent.parent / "meshes" / "cube.stl", seconds_ago=1800)
    assert _counted(_load) == (0, 1)
    assert np.ptp(_load().mesh_vert, axis=0) == pytest.approx([0.2, 0.2, 0.2])
    urdf.write_text(STL_ONLY.replace('lower="-1.0" upper="1.0"', 'lower="-0.5" upper="0.5"'))
    _backdate(urdf, seconds_ago=1800)
    assert _counted(_load) == (0, 1)
    assert list(_load().joint("robot0_shoulder").range) == [-0.5, 0.5]


@pytest.mark.skipif(
    not (converter_available() and importable("collada")),
    reason='converting the COLLADA mesh needs trimesh and pycollada: pip install "robot-assembler[urdf]"',
)
def test_a_converted_mesh_is_a_dependency_of_the_entry(tmp_path: Path) -> None:
    _arm(tmp_path, ARM_URDF)
    assert _counted(_load) == (0, 1)  # converted just now: too recent to store
    (converted,) = converted_dir().glob("cube-*.obj")
    _backdate(converted)
    assert _counted(_load) == (0, 1)  # stored now
    assert _counted(_load) == (1, 0)
    converted.unlink()  # e.g. the cache folder cleaned by hand: the entry's file is gone
    assert _counted(_load) == (0, 1)
    assert converted.is_file()  # converted again


CLI = "import sys; from assembler.cli import run; sys.exit(run())"


@pytest.mark.parametrize("kind", ["urdf", "mjcf"])
def test_a_cached_build_writes_the_bytes_of_an_uncached_one(kind: str, tmp_path: Path) -> None:
    """Found by the hostile-input battery: a URDF robot's cached ``build -o`` lacked the meshes'
    ``content_type`` that its ``--no-cache`` build has (MuJoCo writes it only for meshes it decoded
    in the process). Each build runs in a process of its own, as users run them."""
    if kind == "urdf":
        _arm(tmp_path, ARM_URDF)
        spec = tmp_path / "arm.yaml"
    else:
        (tmp_path / "meshes").mkdir()
        (tmp_path / "meshes" / "tet.obj").write_text(TETRAHEDRON_OBJ)
        (tmp_path / "meshy.xml").write_text(MESH_ARM_MJCF)
        spec = tmp_path / "meshy.yaml"
        spec.write_text("name: Meshy\nmjcf: meshy.xml\n")
        _backdate(tmp_path / "meshes" / "tet.obj", tmp_path / "meshy.xml", spec)
    written = []
    for run, flags in enumerate([[], [], ["--no-cache"]]):  # compiled and stored, cached, uncached
        (tmp_path / f"run{run}").mkdir()
        done = subprocess.run(
            [sys.executable, "-c", CLI, "build", str(spec), "--no-base", "-o", "robot.xml", *flags],
            cwd=tmp_path / f"run{run}",
            capture_output=True,
            text=True,
            timeout=300,
        )
        assert done.returncode == 0, done.stderr
        written.append((tmp_path / f"run{run}" / "robot.xml").read_bytes())
    assert written[0] == written[1] == written[2]
    assert b"content_type=" in written[0]
