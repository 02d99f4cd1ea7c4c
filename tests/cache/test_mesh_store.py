"""The mesh store: a model compiled from stored meshes is identical, in every array, to one compiled
from the OBJ and STL files (robosuite's Panda and GR1, and every mesh attribute that changes
MuJoCo's processing); a damaged entry is a miss, never a wrong mesh; two processes can fill it at
once; a full disk or a folder that cannot be written only means nothing is stored; it stays within
its bound. Every test uses its own store folder and compiles with MuJoCo's in-process asset cache
off, so a compile cannot be answered by an earlier one."""

from __future__ import annotations

import json
import os
import struct
import subprocess
import sys
import textwrap
import time
from collections.abc import Iterator
from pathlib import Path

import mujoco
import numpy as np
import pytest

import assembler
from assembler.cache.file_state import file_digest
from assembler.cache.mesh_data import MSH_CONTENT_TYPE, decode
from assembler.cache.mesh_swap import (
    MeshSwap,
    compile_with_stored_meshes,
    store_meshes,
    use_stored_meshes,
    wait_for_fillers,
)
from assembler.cache.meshes import MAGIC, MeshStore, default_mesh_store
from assembler.files.paths import package_root
from assembler.mjcf.installed_mujoco import mujoco_at_least
from tests.conftest import use_private_cache

HAS_ROBOSUITE = package_root("robosuite") is not None


@pytest.fixture(autouse=True)
def no_asset_cache() -> Iterator[None]:
    """MuJoCo keeps decoded meshes in memory by file name: with it on, the second of two compiles
    could reuse the first's meshes and any comparison would pass."""
    cache = mujoco.mj_getCache()
    capacity = mujoco.mj_getCacheCapacity(cache)
    mujoco.mj_setCacheCapacity(cache, 0)
    yield
    mujoco.mj_setCacheCapacity(cache, capacity)


@pytest.fixture(autouse=True)
def no_filler_left() -> Iterator[None]:
    """No background filler outlives its test (it would write into a folder being removed)."""
    yield
    wait_for_fillers()


@pytest.fixture
def store(tmp_path: Path) -> MeshStore:
    return MeshStore(tmp_path / "meshes", 1 << 30)


# ----- meshes written as a user would have them ------------------------------------------------


def old(path: Path) -> Path:
    """Date ``path`` an hour back: the store takes no file modified in the last seconds."""
    then = time.time() - 3600
    os.utime(path, (then, then))
    return path


def sphere(rings: int = 24, segments: int = 32) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Vertices, texture coordinates and quads of a squashed UV sphere (an irregular inertia)."""
    theta, phi = np.meshgrid(
        np.linspace(0.1, 3.0, rings), np.linspace(0, 2 * np.pi, segments, endpoint=False)
    )
    xyz = np.stack(
        [np.sin(theta) * np.cos(phi) * 0.05, np.sin(theta) * np.sin(phi) * 0.03, np.cos(theta) * 0.08]
    )
    vertices = xyz.reshape(3, -1).T
    uv = np.stack([phi / (2 * np.pi), theta / np.pi]).reshape(2, -1).T
    index = np.arange(rings * segments).reshape(segments, rings)
    quads = [
        (index[s, r], index[s, r + 1], index[(s + 1) % segments, r + 1], index[(s + 1) % segments, r])
        for s in range(segments)
        for r in range(rings - 1)
    ]
    return vertices, uv, np.array(quads)


def write_obj(
    path: Path, shared_indices: bool = True, center: tuple[float, float, float] = (0, 0, 0)
) -> Path:
    """An OBJ with normals, texture coordinates and quads. ``shared_indices=False`` numbers normals
    apart from vertices (``f v/vt/vn`` with different indices), which ``.msh`` cannot hold."""
    vertices, uv, quads = sphere()
    vertices = vertices + np.array(center)
    normals = vertices / np.linalg.norm(vertices, axis=1, keepdims=True)
    lines = [f"v {x:.7f} {y:.7f} {z:.7f}" for x, y, z in vertices]
    lines += [f"vt {u:.6f} {v:.6f}" for u, v in uv]
    lines += [f"vn {x:.6f} {y:.6f} {z:.6f}" for x, y, z in (normals if shared_indices else normals[::-1])]
    count = len(vertices)
    for quad in quads + 1:
        corners = [f"{i}/{i}/{i if shared_indices else count + 1 - i}" for i in quad]
        lines.append("f " + " ".join(corners))
    path.write_text("\n".join(lines) + "\n")
    return old(path)


def write_stl(path: Path) -> Path:
    """A binary STL of the same sphere (corners repeated per triangle, as STL stores them)."""
    vertices, _, quads = sphere()
    triangles = [vertices[[a, b, c]] for a, b, c, d in quads] + [vertices[[a, c, d]] for a, b, c, d in quads]
    body = b"".join(struct.pack("<12fH", 0, 0, 0, *corners.ravel(), 0) for corners in triangles)
    path.write_bytes(b"\0" * 80 + struct.pack("<I", len(triangles)) + body)
    return old(path)


def mesh_spec(files: list[Path], **attributes: object) -> mujoco.MjSpec:
    """A free body with a mesh geom per file, and a box fitted to the first mesh."""
    spec = mujoco.MjSpec()
    body = spec.worldbody.add_body(name="body")
    body.add_freejoint()
    for index, file in enumerate(files):
        mesh = spec.add_mesh(name=f"mesh{index}", file=str(file))
        for name, value in attributes.items():
            setattr(mesh, name, value)
        body.add_geom(type=mujoco.mjtGeom.mjGEOM_MESH, meshname=f"mesh{index}")
    body.add_geom(type=mujoco.mjtGeom.mjGEOM_BOX, meshname="mesh0", pos=[0.2, 0, 0])
    return spec


# ----- comparing two models -------------------------------------------------------------------


def saved(model: mujoco.MjModel) -> bytes:
    buffer = np.empty(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer.tobytes()


def differences(ours: mujoco.MjModel, reference: mujoco.MjModel) -> tuple[list[str], int]:
    """Every attribute of MjModel that differs (arrays by type, shape and bytes; sizes, names and
    asset paths by value; the option, visual and statistic structs through ``mj_saveModel``), and
    how many attributes were compared."""
    found, compared = [], 0
    for name in dir(reference):
        value = getattr(reference, name)
        if name.startswith("_") or callable(value):
            continue
        other = getattr(ours, name)
        if isinstance(value, np.ndarray):
            same = (
                value.dtype == other.dtype
                and value.shape == other.shape
                and value.tobytes() == other.tobytes()
            )
        elif isinstance(value, (bytes, int, float, str)):
            same = value == other
        else:
            continue
        compared += 1
        if not same:
            found.append(name)
    if saved(ours) != saved(reference):
        found.append("mj_saveModel")
    return found, compared


def compile_from(spec: mujoco.MjSpec, store: MeshStore) -> tuple[mujoco.MjModel, MeshSwap]:
    """Compile ``spec`` with its stored meshes, handing nothing to a background filler (the
    context manager would: that has a test of its own)."""
    swap = use_stored_meshes(spec, store)
    try:
        return spec.compile(), swap
    finally:
        swap.restore()


def compile_with_store(spec: mujoco.MjSpec, store: MeshStore) -> tuple[mujoco.MjModel, list[str]]:
    """Compile ``spec`` with every mesh from the store; the model and the files that came from it."""
    model, swap = compile_from(spec, store)
    assert swap.missing == []
    return model, swap.stored


def identity(store: MeshStore, path: Path) -> tuple[str, int]:
    """(content digest, size): what the store knows a file by."""
    found = store.digest(str(path))
    assert found is not None
    return found[0], found[1][0]


def fill(spec: mujoco.MjSpec, store: MeshStore) -> None:
    """A first compile: it stores what it meets (here and now, not in a background process)."""
    swap = compile_from(spec, store)[1]
    store_meshes(swap.missing, store, background=False)


# ----- identical models ---------------------------------------------------------------------


@pytest.mark.skipif(not HAS_ROBOSUITE, reason="needs robosuite's meshes")
@pytest.mark.parametrize("name", ["Panda", "GR1"])
def test_a_robosuite_robot_compiles_identically_from_stored_meshes(name: str, store: MeshStore) -> None:
    robot = assembler.assemble(name)
    reference = robot.build_mjspec().compile()
    fill(robot.build_mjspec(), store)
    spec = robot.build_mjspec()
    files = {mesh.file for mesh in spec.meshes if mesh.file.lower().endswith((".obj", ".stl"))}
    ours, stored = compile_with_store(spec, store)
    assert sorted(stored) == sorted(files)
    found, compared = differences(ours, reference)
    assert found == [] and compared > 400


ATTRIBUTES = [
    {},
    {"scale": [0.5, 2.0, 3.0]},
    {"scale": [-1.0, 1.0, 1.0]},
    {"scale": [-1.0, -1.0, -1.0]},
    {"refpos": [0.01, 0.02, -0.03]},
    {"refquat": [0.7, 0.1, 0.7, 0.1]},
    {"maxhullvert": 8},
    {"smoothnormal": True},
    {"inertia": mujoco.mjtMeshInertia.mjMESH_INERTIA_CONVEX},
    {"inertia": mujoco.mjtMeshInertia.mjMESH_INERTIA_EXACT},
    {"inertia": mujoco.mjtMeshInertia.mjMESH_INERTIA_SHELL},
    {"scale": [-0.5, 1, 2], "refquat": [0, 1, 0, 0], "smoothnormal": True},
]


@pytest.mark.parametrize("attributes", ATTRIBUTES, ids=lambda a: ",".join(a) or "none")
def test_every_mesh_attribute_applies_to_a_stored_mesh_as_to_its_file(
    attributes: dict[str, object], store: MeshStore, tmp_path: Path
) -> None:
    files = [write_obj(tmp_path / "sphere.obj"), write_stl(tmp_path / "sphere.stl")]
    if HAS_ROBOSUITE:
        assets = Path(str(package_root("robosuite"))) / "models/assets/robots"
        files += [assets / "panda/obj_meshes/link0_vis/link0_vis_0.obj", assets / "gr1/meshes/base.STL"]
    reference = mesh_spec(files, **attributes).compile()
    fill(mesh_spec(files, **attributes), store)
    ours, stored = compile_with_store(mesh_spec(files, **attributes), store)
    mirrored = any(value < 0 for value in attributes.get("scale", [1.0]))  # type: ignore[attr-defined]
    # Before MuJoCo 4.0 a mirrored mesh read as .msh is processed slightly differently: read from its file.
    assert len(stored) == (0 if mirrored and not mujoco_at_least(4, 0) else len(files))
    assert differences(ours, reference)[0] == []


def test_the_compile_reads_the_stored_mesh_not_the_file(store: MeshStore, tmp_path: Path) -> None:
    """The control for the tests above: a stored mesh that differs from its file changes the model."""
    obj = write_obj(tmp_path / "sphere.obj")
    fill(mesh_spec([obj]), store)
    digest = identity(store, obj)
    payload = bytearray(store.get("model/obj", *digest) or b"")
    vertices = np.frombuffer(payload, np.float32, count=9, offset=16) * 2
    payload[16 : 16 + 36] = vertices.tobytes()
    store.put("model/obj", *digest, bytes(payload))
    ours, _ = compile_with_store(mesh_spec([obj]), store)
    assert "mesh_vert" in differences(ours, mesh_spec([obj]).compile())[0]


def test_a_stored_mesh_the_compiler_refuses_falls_back_to_the_file(store: MeshStore, tmp_path: Path) -> None:
    obj = write_obj(tmp_path / "sphere.obj")
    digest = identity(store, obj)
    corners = np.array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], np.float32)
    bad = (
        np.array([4, 0, 0, 1], np.int32).tobytes()
        + corners.tobytes()
        + np.array([0, 1, 99], np.int32).tobytes()
    )
    store.put("model/obj", *digest, bad)  # whole and verified, but no mesh MuJoCo accepts
    with pytest.raises(ValueError, match="face"), use_stored_meshes(spec := mesh_spec([obj]), store):
        spec.compile()
    spec = mesh_spec([obj])
    model = compile_with_stored_meshes(spec, spec.compile, store)
    assert differences(model, mesh_spec([obj]).compile())[0] == []
    assert spec.meshes[0].content_type == "" and spec.assets == {}


def test_the_spec_is_as_it_was_after_the_compile(store: MeshStore, tmp_path: Path) -> None:
    files = [write_obj(tmp_path / "sphere.obj"), write_stl(tmp_path / "sphere.stl")]
    fill(mesh_spec(files), store)
    spec = mesh_spec(files)
    spec.meshes[1].content_type = "model/stl"
    spec.assets = {"notes.txt": b"kept"}
    with use_stored_meshes(spec, store) as swap:
        assert [mesh.content_type for mesh in spec.meshes] == [MSH_CONTENT_TYPE] * 2
        spec.compile()
    assert len(swap.stored) == 2
    assert [mesh.content_type for mesh in spec.meshes] == ["", "model/stl"]
    assert spec.assets == {"notes.txt": b"kept"}


def test_an_obj_whose_normals_are_numbered_apart_is_left_to_mujoco(store: MeshStore, tmp_path: Path) -> None:
    obj = write_obj(tmp_path / "apart.obj", shared_indices=False)
    assert decode(str(obj)) is None
    fill(mesh_spec([obj]), store)
    model, swap = compile_from(mesh_spec([obj]), store)
    assert swap.stored == [] and swap.missing == []  # known: no .msh form, not decoded again
    assert differences(model, mesh_spec([obj]).compile())[0] == []


def test_the_same_content_at_another_path_is_found_without_decoding(store: MeshStore, tmp_path: Path) -> None:
    first = write_obj(tmp_path / "a.obj")
    fill(mesh_spec([first]), store)
    copy = tmp_path / "copy" / "b.obj"
    copy.parent.mkdir()
    copy.write_bytes(first.read_bytes())
    _, stored = compile_with_store(mesh_spec([old(copy)]), store)
    assert stored == [str(copy)]


def test_a_new_file_of_a_size_no_entry_has_is_not_hashed(store: MeshStore, tmp_path: Path) -> None:
    known = write_obj(tmp_path / "known.obj")
    fill(mesh_spec([known]), store)
    records = sorted(store.directory.glob("*.src"))
    new = write_stl(tmp_path / "new.stl")
    _, swap = compile_from(mesh_spec([known, new]), store)
    assert swap.stored == [str(known)] and swap.missing == [(str(new), "model/stl")]
    assert sorted(store.directory.glob("*.src")) == records  # hashing would have recorded it


def test_an_edited_mesh_is_a_miss_and_a_file_edited_a_moment_ago_is_not_stored(
    store: MeshStore, tmp_path: Path
) -> None:
    obj = write_obj(tmp_path / "sphere.obj")
    fill(mesh_spec([obj]), store)
    write_obj(obj, center=(0.01, 0, 0))
    os.utime(obj)  # modified now
    for _ in range(2):
        model, swap = compile_from(mesh_spec([obj]), store)
        assert swap.stored == [] and swap.missing == [(str(obj), "model/obj")]
        assert differences(model, mesh_spec([obj]).compile())[0] == []
        store_meshes(swap.missing, store, background=False)  # too recent: nothing is stored


# ----- damaged entries and records ------------------------------------------------------------


def test_a_flipped_byte_anywhere_in_an_entry_is_a_miss_and_removes_it(
    store: MeshStore, tmp_path: Path
) -> None:
    obj = write_obj(tmp_path / "sphere.obj")
    fill(mesh_spec([obj]), store)
    (entry,) = store.directory.glob("*.msh")
    whole = entry.read_bytes()
    digest = identity(store, obj)
    assert store.get("model/obj", *digest) == whole[len(MAGIC) + 32 :]
    positions = sorted(
        {0, 7, 8, 39, 40, 41, 44, 55, len(whole) // 2, len(whole) - 1} | set(range(0, len(whole), 997))
    )
    for position in positions:
        damaged = bytearray(whole)
        damaged[position] ^= 0x01
        entry.write_bytes(damaged)
        assert store.get("model/obj", *digest) is None, position
        assert not entry.exists()
    for cut in (0, 20, len(whole) - 1):
        entry.write_bytes(whole[:cut])
        assert store.get("model/obj", *digest) is None
    model, swap = compile_from(mesh_spec([obj]), store)
    assert swap.missing == [(str(obj), "model/obj")]
    assert differences(model, mesh_spec([obj]).compile())[0] == []


def test_a_damaged_record_is_ignored_and_the_file_hashed_again(store: MeshStore, tmp_path: Path) -> None:
    obj = write_obj(tmp_path / "sphere.obj")
    fill(mesh_spec([obj]), store)
    (record,) = store.directory.glob("*.src")
    text = record.read_bytes()
    digest = json.loads(text)["digest"].encode()
    other = bytes(f"{int(digest, 16) ^ 1:0{len(digest)}x}", "ascii")
    record.write_bytes(text.replace(digest, other))
    _, stored = compile_with_store(mesh_spec([obj]), store)
    assert stored == [str(obj)]
    assert digest in record.read_bytes()  # hashed again and recorded again


# ----- several processes, full disks, read-only folders ---------------------------------------

FILLER = textwrap.dedent(
    """
    import sys
    from pathlib import Path
    from assembler.cache.mesh_fill import fill
    from assembler.cache.meshes import MeshStore
    print(fill(MeshStore(Path(sys.argv[1]), 1 << 30), zip(sys.argv[2::2], sys.argv[3::2])))
    """
)


def test_two_processes_filling_the_store_at_once_both_succeed_and_every_entry_is_whole(
    store: MeshStore, tmp_path: Path
) -> None:
    files = [write_obj(tmp_path / f"sphere{i}.obj", center=(i * 0.01, 0, 0)) for i in range(6)]
    files.append(write_stl(tmp_path / "sphere.stl"))
    meshes = [part for file in files for part in (str(file), f"model/{file.suffix[1:]}")]
    workers = [
        subprocess.Popen(
            [sys.executable, "-c", FILLER, str(store.directory), *meshes],
            stdout=subprocess.PIPE,
            stderr=subprocess.PIPE,
            text=True,
        )
        for _ in range(2)
    ]
    results = [worker.communicate(timeout=300) for worker in workers]
    assert [worker.returncode for worker in workers] == [0, 0], results
    assert sum(int(out) for out, _ in results) == len(files)  # each file decoded once in all
    assert len(list(store.directory.glob("*.msh"))) == len(files)
    assert not list(store.directory.glob(".*.tmp")) and not list(store.directory.glob("*.claim"))
    ours, stored = compile_with_store(mesh_spec(files), store)
    assert len(stored) == len(files)
    assert differences(ours, mesh_spec(files).compile())[0] == []


FULL_DISK = textwrap.dedent(
    """
    import resource, signal, sys
    from pathlib import Path
    import mujoco
    from assembler.cache.mesh_swap import store_meshes, use_stored_meshes
    from assembler.cache.meshes import MeshStore
    signal.signal(signal.SIGXFSZ, signal.SIG_IGN)  # a write past the limit fails with EFBIG
    resource.setrlimit(resource.RLIMIT_FSIZE, (4096, 4096))
    spec = mujoco.MjSpec.from_string(sys.argv[2])
    store = MeshStore(Path(sys.argv[1]), 1 << 30)
    swap = use_stored_meshes(spec, store)
    model = spec.compile()
    swap.restore()
    store_meshes(swap.missing, store, background=False)
    print(model.nmeshvert)
    """
)


def test_a_full_disk_stores_nothing_and_the_model_is_the_same(store: MeshStore, tmp_path: Path) -> None:
    files = [write_obj(tmp_path / "sphere.obj"), write_stl(tmp_path / "sphere.stl")]
    xml = mesh_spec(files).to_xml()
    result = subprocess.run(
        [sys.executable, "-c", FULL_DISK, str(store.directory), xml],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert result.returncode == 0, result.stderr
    assert int(result.stdout) == mesh_spec(files).compile().nmeshvert
    assert list(store.directory.glob("*.msh")) == []  # every entry is larger than the limit
    assert list(store.directory.glob(".*.tmp")) == []  # and no half-written file is left
    model, swap = compile_from(mesh_spec(files), store)
    assert len(swap.missing) == 2
    assert differences(model, mesh_spec(files).compile())[0] == []


def test_a_store_folder_that_cannot_be_written_only_means_no_store(tmp_path: Path) -> None:
    files = [write_obj(tmp_path / "sphere.obj")]
    blocker = tmp_path / "a-file"
    blocker.write_text("not a folder")
    store = MeshStore(blocker / "meshes", 1 << 30)
    fill(mesh_spec(files), store)
    model, swap = compile_from(mesh_spec(files), store)
    assert swap.stored == [] and len(swap.missing) == 1
    assert differences(model, mesh_spec(files).compile())[0] == []


def test_a_read_only_store_still_answers(store: MeshStore, tmp_path: Path) -> None:
    files = [write_obj(tmp_path / "sphere.obj")]
    fill(mesh_spec(files), store)
    before = sorted(path.name for path in store.directory.iterdir())
    store.directory.chmod(0o555)
    try:
        ours, stored = compile_with_store(mesh_spec(files), store)
        fill(mesh_spec([write_stl(tmp_path / "sphere.stl")]), store)  # new files: nothing to write to
        if not os.access(store.directory, os.W_OK):  # root writes anyway
            assert sorted(path.name for path in store.directory.iterdir()) == before
    finally:
        store.directory.chmod(0o755)
    assert stored == [str(files[0])]
    assert differences(ours, mesh_spec(files).compile())[0] == []


# ----- bound, clean-up, settings -------------------------------------------------------------


def test_eviction_keeps_the_bound_and_drops_the_least_recently_used_first(
    store: MeshStore, tmp_path: Path
) -> None:
    a, b, c = (write_obj(tmp_path / f"{name}.obj", center=(i * 0.01, 0, 0)) for i, name in enumerate("abc"))
    fill(mesh_spec([a]), store)
    fill(mesh_spec([b]), store)
    one = max(path.stat().st_size for path in store.directory.glob("*.msh"))
    store.max_bytes = store.info().total_bytes + one // 2
    compile_with_store(mesh_spec([a]), store)  # a is used after b
    fill(mesh_spec([c]), store)
    assert store.info().total_bytes <= store.max_bytes and store.info().entries == 2
    swap = use_stored_meshes(mesh_spec([a, b, c]), store)
    assert swap.stored == [str(a), str(c)] and swap.missing == [(str(b), "model/obj")]


def test_stale_claims_and_temporary_files_are_removed_and_a_fresh_claim_holds(
    store: MeshStore, tmp_path: Path
) -> None:
    obj = write_obj(tmp_path / "sphere.obj")
    digest = (file_digest(obj), obj.stat().st_size)
    claim = store.claim("model/obj", *digest)
    assert claim is not None and store.claim("model/obj", *digest) is None
    fill(mesh_spec([obj]), store)
    assert not store.has("model/obj", *digest)  # another process holds the claim
    stale = store.directory / f".123-{'0' * 40}.msh.abc123.tmp"
    stale.write_bytes(b"half")
    notes = store.directory / "notes.txt"
    notes.write_text("not the store's")
    for path in (claim, stale, notes):
        os.utime(path, (time.time() - 3600,) * 2)
    fill(mesh_spec([obj]), store)  # the claim is old: taken over
    assert store.has("model/obj", *digest) and not claim.exists() and not stale.exists() and notes.exists()
    assert store.clear().entries == 1 and [path.name for path in store.directory.iterdir()] == ["notes.txt"]


def test_the_background_filler_stores_what_a_compile_met_and_ignores_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    use_private_cache(tmp_path / "cache", monkeypatch)
    decoy = tmp_path / "work" / "assembler"
    decoy.mkdir(parents=True)
    (decoy / "__init__.py").write_text(f"open({str(tmp_path / 'decoy-ran')!r}, 'w')\n")
    monkeypatch.chdir(decoy.parent)
    files = [write_obj(tmp_path / "sphere.obj"), write_stl(tmp_path / "sphere.stl")]
    with use_stored_meshes(spec := mesh_spec(files)) as swap:
        spec.compile()
    assert len(swap.missing) == 2
    wait_for_fillers()
    assert not (tmp_path / "decoy-ran").exists()
    store = default_mesh_store()
    assert store is not None and store.directory == tmp_path / "cache" / "meshes"
    assert store.max_bytes == 2 * 1024**3  # the cache folder's one bound
    assert compile_with_store(mesh_spec(files), store)[1] == [str(file) for file in files]


def test_with_the_cache_off_nothing_changes(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))
    monkeypatch.setenv("ASSEMBLER_NO_CACHE", "1")
    files = [write_obj(tmp_path / "sphere.obj")]
    with use_stored_meshes(spec := mesh_spec(files)) as swap:
        spec.compile()
    assert swap.store is None and swap.missing == [] and not (tmp_path / "cache").exists()


def test_a_process_that_leaves_a_filler_at_work_exits_without_a_shutdown_warning(tmp_path: Path) -> None:
    # The filler runs in its own session and outlives the process that started it, on purpose;
    # Python used to print "ResourceWarning: subprocess N is still running" at that process's exit.
    files = [write_obj(tmp_path / "sphere.obj"), write_stl(tmp_path / "sphere.stl")]
    script = textwrap.dedent(
        f"""
        from assembler.cache.mesh_swap import use_stored_meshes
        from tests.cache.test_mesh_store import mesh_spec
        with use_stored_meshes(spec := mesh_spec([Path(p) for p in {[str(f) for f in files]!r}])) as swap:
            spec.compile()
        assert len(swap.missing) == 2
        """
    )
    environment = {**os.environ, "ASSEMBLER_CACHE_DIR": str(tmp_path / "cache")}
    environment.pop("ASSEMBLER_NO_CACHE", None)
    done = subprocess.run(
        [sys.executable, "-W", "default", "-c", "from pathlib import Path\n" + script],
        cwd=Path(__file__).resolve().parents[2],
        env=environment,
        capture_output=True,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stderr) == (0, "")
    deadline = time.monotonic() + 60
    while len(list((tmp_path / "cache" / "meshes").glob("*.msh"))) < 2 and time.monotonic() < deadline:
        time.sleep(0.1)  # the filler finishes on its own
    assert len(list((tmp_path / "cache" / "meshes").glob("*.msh"))) == 2
