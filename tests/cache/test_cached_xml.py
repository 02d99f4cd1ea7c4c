"""The emitted XML kept in the compiled-model cache: what ``get_xml`` returns from it is byte for
byte what a fresh emission gives; a damaged XML file is a miss; an entry made by ``get_model``
gains its XML on the first ``get_xml``; a spec the user has read is emitted as it is."""

from __future__ import annotations

import os
import time
from collections.abc import Iterator
from pathlib import Path

import pytest

import assembler
from assembler.cache.key import cache_key
from assembler.cache.mesh_swap import wait_for_fillers
from assembler.compiler import service
from assembler.compiler.service import default_store, wait_for_writes
from assembler.files.paths import package_root
from assembler.mjcf.emit import to_xml
from tests.conftest import MESH_ARM_MJCF, TETRAHEDRON_OBJ, use_private_cache

ROBOSUITE = package_root("robosuite") is not None
needs_robosuite = pytest.mark.skipif(not ROBOSUITE, reason="robosuite is not installed")


@pytest.fixture(autouse=True)
def private_cache(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Iterator[Path]:
    """A fresh cache folder (models and meshes) per test."""
    folder = use_private_cache(tmp_path / "model-cache", monkeypatch)
    yield folder
    wait_for_writes()


def fresh_xml(name: str) -> str:
    """The XML as emitted without any cache: compiled from the files, then ``to_xml``."""
    robot = assembler.assemble(name)
    robot.get_model(cache=False)
    return to_xml(robot.mjspec)


def entry_of(name: str) -> tuple[Path, str, str]:
    """(cache folder, model file, XML file) of a robot's entry ("" when it has none)."""
    store = default_store()
    entry = store.entry(cache_key(assembler.assemble(name).build_inputs()) or "")
    assert entry is not None
    return store.directory, entry.model, entry.xml


@pytest.mark.parametrize(
    "name",
    ["Sparrow7", pytest.param("Panda", marks=needs_robosuite), pytest.param("GR1", marks=needs_robosuite)],
)
def test_the_stored_xml_is_byte_for_byte_a_fresh_emission(name: str) -> None:
    expected = fresh_xml(name)
    first = assembler.assemble(name).get_xml()  # compiled once, emitted from that spec, kept
    wait_for_writes()
    hits = service.counts.hits
    second = assembler.assemble(name).get_xml()  # from the entry
    assert service.counts.hits == hits + 1
    assert first == expected and second == expected


@needs_robosuite
def test_xml_emitted_with_stored_meshes_is_the_same_text() -> None:
    """The second compile inside MuJoCo's XML writer reads stored meshes too; the text must not show it."""
    assembler.assemble("Panda").get_model(cache=False)  # the meshes' first contact: fills the mesh store
    wait_for_fillers()
    expected = fresh_xml("Panda")
    assert assembler.assemble("Panda").get_xml() == expected


def test_xml_emitted_with_meshes_from_the_mesh_store_is_the_same_text(tmp_path: Path) -> None:
    """Without robosuite too: an OBJ mesh used twice, read from the mesh store by both compiles."""
    folder = tmp_path / "arm"
    (folder / "meshes").mkdir(parents=True)
    (folder / "meshes" / "tet.obj").write_text(TETRAHEDRON_OBJ)
    (folder / "meshy.xml").write_text(MESH_ARM_MJCF)
    (folder / "mesh_arm.yaml").write_text("name: MeshArm\nmjcf: meshy.xml\n")
    for path in [*folder.rglob("*"), folder]:
        os.utime(path, (time.time() - 3600,) * 2)
    assembler.register_specs(folder)
    assembler.assemble("MeshArm").get_model(store=False)  # first contact: a filler stores the mesh
    wait_for_fillers()
    expected = fresh_xml("MeshArm")
    assert list((default_store().directory / "meshes").rglob("*.msh*")), "the mesh was not stored"
    assert assembler.assemble("MeshArm").get_xml() == expected


def test_a_damaged_xml_file_is_a_miss_and_is_replaced() -> None:
    expected = assembler.assemble("Sparrow7").get_xml()
    wait_for_writes()
    folder, _, xml = entry_of("Sparrow7")
    damaged = bytearray((folder / xml).read_bytes())
    damaged[len(damaged) // 2] ^= 1
    (folder / xml).write_bytes(bytes(damaged))
    misses = service.counts.misses
    assert assembler.assemble("Sparrow7").get_xml() == expected
    assert service.counts.misses == misses + 1
    wait_for_writes()
    _, _, replaced = entry_of("Sparrow7")
    assert not (folder / xml).exists() and replaced != xml and (folder / replaced).read_text() == expected


def test_an_entry_made_by_get_model_gains_its_xml_on_the_first_get_xml() -> None:
    assembler.assemble("Sparrow7").get_model()
    wait_for_writes()
    folder, model, xml = entry_of("Sparrow7")
    assert xml == ""
    text = assembler.assemble("Sparrow7").get_xml()
    wait_for_writes()
    _, model_after, xml_after = entry_of("Sparrow7")
    assert model_after == model  # the model it held is kept, not written again
    assert (folder / xml_after).read_text() == text == fresh_xml("Sparrow7")


def test_an_edited_mjspec_is_emitted_as_it_is_never_from_the_cache() -> None:
    assembler.assemble("Sparrow7").get_xml()
    wait_for_writes()
    robot = assembler.assemble("Sparrow7")
    robot.mjspec.joint("robot0_joint1").armature = 7.25
    assert 'armature="7.25"' in robot.get_xml()
    assert 'armature="7.25"' not in assembler.assemble("Sparrow7").get_xml()


def test_clearing_the_cache_removes_the_xml_files_too() -> None:
    assembler.assemble("Sparrow7").get_xml()
    wait_for_writes()
    folder, _, xml = entry_of("Sparrow7")
    assert (folder / xml).exists()
    service.clear(default_store())
    assert not list(folder.glob("*.xml"))


def test_eviction_counts_and_removes_the_xml_files(monkeypatch: pytest.MonkeyPatch) -> None:
    for name in ("Sparrow7", "Finch6"):
        assembler.assemble(name).get_xml()
        wait_for_writes()
    store = default_store()
    total = sum(path.stat().st_size for path in store.directory.rglob("*") if path.is_file())
    kept = sum(path.stat().st_size for path in store.directory.iterdir() if "json" in path.name)
    records = sum(path.stat().st_size for path in (store.directory / "requests").glob("*.json"))
    # One bound counts every part: room for everything but one byte of the models (records go first).
    monkeypatch.setenv("ASSEMBLER_CACHE_MAX_BYTES", str(total - records - 1))
    default_store().evict()
    left = sorted(path.suffix for path in store.directory.iterdir() if path.is_file())
    assert left == [".json", ".mjb", ".xml"] and kept > 0
