"""Compile a spec with its meshes read from the mesh store: the one call the compile path needs.

::

    model = compile_with_stored_meshes(spec, spec.compile)

    with use_stored_meshes(spec):      # the same, without the fallback below
        model = spec.compile()

Before the compile, every OBJ and STL mesh whose file is in the store (:mod:`assembler.cache.meshes`)
is given to MuJoCo as its stored ``.msh`` bytes, in memory under the mesh's own file name
(``spec.assets``), with ``content_type`` set to ``.msh``; nothing else of the mesh changes, and the
model is identical to one compiled from the files. On leaving the block the spec is as it was, and
the files that were not in the store are handed to a background process that decodes and stores
them (:mod:`assembler.cache.mesh_fill`): MuJoCo has just decoded them for this compile, so the first
contact costs this process a stat per file, and the next process finds them.

A compile that fails with stored meshes is run once more from the files, so the store can never
turn a model that compiles into an error (the error a user sees is the files' own).
"""

from __future__ import annotations

import atexit
import importlib
import json
import os
import subprocess
import sys
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from types import TracebackType
from typing import TypeVar

import mujoco

from assembler.cache.file_state import stat_of as file_stat
from assembler.cache.mesh_data import MSH_CONTENT_TYPE, mesh_kind, msh_supported
from assembler.cache.mesh_fill import fill
from assembler.cache.meshes import MeshStore, default_mesh_store
from assembler.mjcf.installed_mujoco import mujoco_at_least

Mesh = tuple[str, str]
"""(absolute file path, decoder content type) of a mesh file."""

Result = TypeVar("Result")

_MISSING = b"\0missing"
_fillers: list[subprocess.Popen[bytes]] = []
_handed: set[tuple[str, Mesh]] = set()
"""(store folder, mesh) given to a filler by this process: a loop that compiles the same new
meshes again and again starts one filler for them, not one per compile."""


@dataclass
class MeshSwap:
    """What :func:`use_stored_meshes` changed in a spec (undone by :meth:`restore`), and what it found."""

    spec: mujoco.MjSpec
    store: MeshStore | None
    stored: list[str] = field(default_factory=list)
    """Files whose meshes came from the store."""

    missing: list[Mesh] = field(default_factory=list)
    """Files not in the store yet: MuJoCo decodes them in this compile; :func:`store_meshes` keeps them."""

    _changed: list[tuple[mujoco.MjsMesh, str]] = field(default_factory=list)
    _added: list[str] = field(default_factory=list)

    @property
    def content_types(self) -> list[tuple[str, str]]:
        """(mesh name, its own content type) of every mesh now reading stored bytes."""
        return [(mesh.name, content_type) for mesh, content_type in self._changed]

    def restore(self) -> None:
        """Put back every mesh's ``content_type`` and take the stored meshes out of ``spec.assets``
        (a live dict: assigning to it adds to it, so the additions are removed one by one)."""
        for mesh, content_type in self._changed:
            mesh.content_type = content_type
        assets = self.spec.assets
        for path in self._added:
            assets.pop(path, None)
        self._changed, self._added = [], []

    def __enter__(self) -> MeshSwap:
        return self

    def __exit__(
        self, kind: type[BaseException] | None, error: BaseException | None, trace: TracebackType | None
    ) -> None:
        self.restore()
        if self.store is not None and self.missing:
            store_meshes(self.missing, self.store)


def _look_up(store: MeshStore, mesh: Mesh, sizes: set[int]) -> bytes | None:
    """The stored bytes of ``mesh`` (empty: MuJoCo reads the file), _MISSING, or None when the
    file cannot be read steadily (the compile reports a missing file its own way). A file with
    no record is hashed only if an entry of its size exists: a new mesh costs a stat, not a hash."""
    path, kind = mesh
    try:
        stat = file_stat(path)
    except OSError:
        return None
    digest = store.recorded(path, stat)
    if digest is None:
        if stat[0] not in sizes:
            return _MISSING
        found = store.digest(path)
        if found is None:
            return None
        digest, stat = found
    payload = store.get(kind, digest, stat[0])
    return _MISSING if payload is None else payload


def _swappable(spec: mujoco.MjSpec) -> dict[Mesh, list[mujoco.MjsMesh]]:
    """The spec's meshes by file, for files every mesh reads through the same decoder."""
    by_path: dict[str, list[mujoco.MjsMesh]] = {}
    for mesh in spec.meshes:
        if mesh.file and not _mirrored_before_4(mesh):
            by_path.setdefault(mesh.file, []).append(mesh)
    found: dict[Mesh, list[mujoco.MjsMesh]] = {}
    for path, meshes in by_path.items():
        kinds = {mesh_kind(path, mesh.content_type) for mesh in meshes}
        if len(kinds) == 1 and (kind := kinds.pop()) is not None:
            found[(path, kind)] = meshes
    return found


def _mirrored_before_4(mesh: mujoco.MjsMesh) -> bool:
    """A mirrored mesh (a negative scale) on MuJoCo before 4.0, which processes one decoded from a
    file and one read as ``.msh`` slightly differently (measured on 3.9 to 3.17): read from its file."""
    return not mujoco_at_least(4, 0) and any(value < 0 for value in mesh.scale)


def use_stored_meshes(spec: mujoco.MjSpec, store: MeshStore | None = None) -> MeshSwap:
    """Point every OBJ and STL mesh of ``spec`` whose file is stored at its stored ``.msh``; use the
    result as a context manager around the compile (or call ``restore()`` after it).

    ``store``: the default one (the cache folder's ``meshes/``) unless given; with the cache off,
    or a MuJoCo that cannot read ``.msh`` from memory, nothing changes. Files already given in
    ``spec.assets``, meshes with relative paths and a spec with ``strippath`` are left alone.
    """
    store = store if store is not None else default_mesh_store()
    swap = MeshSwap(spec, store)
    if store is None or spec.strippath or not msh_supported():
        return swap
    assets = dict(spec.assets)
    meshes = {mesh: users for mesh, users in _swappable(spec).items() if mesh[0] not in assets}
    sizes = store.sizes() if meshes else set()
    if len(meshes) > 1:
        # concurrent.futures imported here (~4 ms): a cached answer imports this module, compiles nothing
        futures = importlib.import_module("concurrent.futures")
        with futures.ThreadPoolExecutor(min(4, os.cpu_count() or 1)) as pool:  # hashing releases the GIL
            found = list(pool.map(lambda mesh: _look_up(store, mesh, sizes), meshes))
    else:
        found = [_look_up(store, mesh, sizes) for mesh in meshes]
    added: dict[str, bytes] = {}
    for (mesh, users), payload in zip(meshes.items(), found, strict=True):
        if payload is _MISSING:
            swap.missing.append(mesh)
        elif payload:
            added[mesh[0]] = payload
            swap.stored.append(mesh[0])
            for user in users:
                swap._changed.append((user, user.content_type))
                user.content_type = MSH_CONTENT_TYPE
    if added:
        spec.assets = {**assets, **added}
        swap._added = list(added)
    return swap


def compile_with_stored_meshes(
    spec: mujoco.MjSpec, compile_spec: Callable[[], Result], store: MeshStore | None = None
) -> Result:
    """``compile_spec()`` (a compile of ``spec``) with ``spec``'s meshes read from the store, the
    spec restored afterwards and new mesh files handed to a background filler. If the compile
    fails with stored meshes in, it runs again from the files and that result or error stands."""
    with use_stored_meshes(spec, store) as swap:
        if not swap.stored:
            return compile_spec()
        try:
            return compile_spec()
        except ValueError:
            pass
    return compile_spec()


def compile_from_store(spec: mujoco.MjSpec) -> mujoco.MjModel:
    """``spec.compile()`` with stored meshes (see :func:`compile_with_stored_meshes`)."""
    return compile_with_stored_meshes(spec, spec.compile)


def store_meshes(meshes: Iterable[Mesh], store: MeshStore, background: bool = True) -> None:
    """Decode ``meshes`` and keep them in ``store``: in a process of its own that outlives this
    one (lowered priority, output discarded), or here and now with ``background=False``."""
    meshes = list(meshes)
    if not background:
        fill(store, meshes)
        return
    meshes = [mesh for mesh in meshes if (str(store.directory), mesh) not in _handed]
    if not meshes or not sys.executable:
        return
    arguments = [str(store.directory), str(store.max_bytes)] + [part for mesh in meshes for part in mesh]
    options: dict[str, object] = {"start_new_session": True} if os.name == "posix" else {}
    try:
        filler = subprocess.Popen(
            [sys.executable, "-I", "-c", _FILLER, json.dumps(_import_path()), *arguments],
            stdin=subprocess.DEVNULL,
            stdout=subprocess.DEVNULL,
            stderr=subprocess.DEVNULL,
            **options,  # type: ignore[call-overload]
        )
    except OSError:
        return  # no process to spare: the next compile decodes them again
    _handed.update((str(store.directory), mesh) for mesh in meshes)
    _fillers[:] = [process for process in _fillers if process.poll() is None]
    _fillers.append(filler)


def _leave_fillers_running() -> None:
    """At exit, let the fillers still at work finish on their own (they run in their own session):
    marked as ended here, so Python does not warn at shutdown that a subprocess is still running."""
    for process in _fillers:
        if process.poll() is None:
            process.returncode = 0  # not waited for, on purpose


atexit.register(_leave_fillers_running)


_FILLER = (
    "import json, sys; sys.path[:] = json.loads(sys.argv.pop(1)); "
    "from assembler.cache.mesh_fill import main; sys.exit(main(sys.argv[1:]))"
)
"""The filler's start: isolated (``-I``: no working folder or PYTHON* variables on its path), with
this process's import path, so it runs this very assembler and MuJoCo and nothing a folder holds."""


def _import_path() -> list[str]:
    return [os.path.abspath(entry) for entry in sys.path if entry]


def wait_for_fillers() -> None:
    """Block until every background filler this process started is done (tests, benchmarks)."""
    while _fillers:
        _fillers.pop().wait()
