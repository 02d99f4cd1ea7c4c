"""The compile service: an assembly's build inputs in, a compiled model with its ``home`` keyframe out,
from the cache when its inputs and files are unchanged.

Models build MuJoCo specs; this module compiles them. A lookup hashes the build inputs
(:mod:`assembler.cache.key`) and, on a hit, never calls the build: no MJCF is parsed. On a miss the
build callback assembles the spec, it is compiled once with its ``home`` keyframe, and the entry is
written in the background with every file the compile read. The keyframe travels with the model
(:class:`~assembler.compiler.keyframe.Keyframe`), so an assembly built later (for its XML) carries
exactly the keyframe of the model that was handed out. An entry also keeps the assembly's emitted
XML once it was asked for (:func:`compile_xml`), so a repeated ``get_xml`` neither builds nor
compiles. The lookup itself (the store, a stored model, an assembly's key, the counts) is
:mod:`assembler.compiler.stored`, which a cached answer imports without this module.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import TypeVar

import mujoco

from assembler.cache.dependencies import Recorder, asset_files, verify
from assembler.cache.folder import FolderInfo
from assembler.cache.folder import clear as clear_folder
from assembler.cache.mesh_swap import wait_for_fillers
from assembler.cache.meshes import default_mesh_store
from assembler.cache.store import ModelStore
from assembler.cache.store import wait_for_writes as wait_for_entries
from assembler.compiler.compile import compile_and_emit, compile_home
from assembler.compiler.keyframe import Keyframe
from assembler.compiler.stored import counts as counts  # the lookup's names, still asked for here
from assembler.compiler.stored import default_store as default_store
from assembler.compiler.stored import entry_key as entry_key
from assembler.compiler.stored import load_entry
from assembler.compiler.stored import recent as _recent
from assembler.files.inputs import note_inputs


@dataclass(frozen=True)
class Assembly:
    """What a model's build hands the compiler."""

    mjspec: mujoco.MjSpec
    """The assembled spec (robot, base, grippers, placement), without its keyframe."""

    home: Mapping[str, float]
    """Joint name -> initial position for the ``home`` keyframe (others stay at qpos0)."""

    read_files: Mapping[str, tuple[int, int]]
    """Files read before the compile (each part's MJCF and includes), with their (size, mtime_ns) then."""

    label: str
    """What was compiled, for people reading the cache folder (e.g. ``Panda0 + RethinkMount0``)."""

    what: str
    """How a compile error names it: ``specs/panda.yaml:1:1: robot 'Panda'``."""


@dataclass(frozen=True)
class CompiledModel:
    """A compiled model and its ``home`` keyframe."""

    model: mujoco.MjModel
    keyframe: Keyframe


def clear(store: ModelStore) -> FolderInfo:
    """Empty the cache folder of ``store`` (every part: models, meshes, request records, converted
    meshes, robosuite part files) and forget the models this process kept from it; returns what it
    held (and what could not be removed)."""
    _recent.forget(str(store.directory))
    return clear_folder(store.directory)


def wait_for_writes() -> None:
    """Block until every cache entry and decoded mesh this process started writing is in place
    (tests, benchmarks); the interpreter waits for entries at exit by itself, not for mesh fillers."""
    wait_for_entries()
    wait_for_fillers()


def _recorder(assembly: Assembly) -> Recorder:
    """The recorder of an assembly's files; mesh files the mesh store hashed are not hashed again."""
    meshes = default_mesh_store()
    known = meshes.known_digest if meshes is not None else None
    return Recorder([*assembly.read_files, *asset_files(assembly.mjspec)], assembly.read_files, known)


def _built(build: Callable[[], Assembly]) -> Assembly:
    """``build()``, its files noted as inputs no output may be written over."""
    assembly = build()
    note_inputs([*assembly.read_files, *asset_files(assembly.mjspec)])
    return assembly


Answer = TypeVar("Answer")


def _on_miss(patched: Callable[[], Answer | None] | None) -> Answer | None:
    """A cache miss, counted, and answered by ``patched()`` when it can (made without a compile; not
    stored, see :mod:`assembler.patch.robot_variant`); None: build and compile."""
    counts.misses += 1
    answer = patched() if patched is not None else None
    if answer is not None:
        counts.patched += 1
    return answer


def compile_assembly(assembly: Assembly, meshes: bool = True) -> CompiledModel:
    """Compile ``assembly`` with its ``home`` keyframe (written into its spec too), reading meshes
    decoded before from the mesh store unless ``meshes`` is False; the model cache is not used."""
    model = compile_home(assembly.mjspec, assembly.home, assembly.what, meshes)
    return CompiledModel(model, Keyframe.of(model))


def compile_model(
    key: str | None,
    build: Callable[[], Assembly],
    cache: bool = True,
    store: bool = True,
    patched: Callable[[], CompiledModel | None] | None = None,
) -> CompiledModel:
    """The model of the cache entry ``key`` (see :func:`entry_key`): from the cache, or ``build()``
    compiled and (with ``store``) kept for next time; with no key, compiled every time. On a miss,
    ``patched()`` is asked first: a model it returns (made without a compile) is the answer, and
    is not stored (see :mod:`assembler.patch.robot_variant` for why)."""
    if key is None:
        counts.bypassed += 1
        return compile_assembly(_built(build), meshes=cache)
    keep = store
    models = default_store()
    model = load_entry(key)
    if model is not None:
        return CompiledModel(model, Keyframe.of(model))
    answer = _on_miss(patched)
    if answer is not None:
        return answer
    assembly = _built(build)
    recorder = _recorder(assembly)
    compiled = compile_assembly(assembly)
    if keep:
        models.save(key, compiled.model, recorder, assembly.label)
    return compiled


def compile_xml(
    key: str | None,
    build: Callable[[], Assembly],
    cache: bool = True,
    store: bool = True,
    meshes: bool = True,
    patched: Callable[[], tuple[CompiledModel, str] | None] | None = None,
) -> tuple[CompiledModel | None, str]:
    """The emitted MJCF of the cache entry ``key`` (see :func:`entry_key`), and the model when one
    was compiled.

    From the cache entry when it holds the XML (no build, no compile, the model not even read:
    None is returned for it); else built once, compiled once and emitted from that same spec
    (:func:`~assembler.compiler.compile.compile_and_emit`), and (with ``store``) kept: the XML is
    added to a current entry that lacks it, or stored with the model as a new entry. ``meshes``
    False reads meshes from their files rather than the mesh store: a process compiling the same
    meshes many times (variants) gains from MuJoCo's own asset cache, which keeps meshes read from
    files processed (hulls, normals), and not those given in memory. On a miss, and with the cache
    off (``key`` None), ``patched()`` is asked first; its answer is not stored. Asking it in both
    keeps a written file's bytes independent of what the cache holds: a robot with overrides is
    written as its plain robot's text with the values written in, or compiled, by the overrides alone.
    """
    if key is None:
        counts.bypassed += 1
        answered = patched() if patched is not None else None  # the text a cached answer would write
        if answered is not None:
            counts.patched += 1
            return answered
        assembly = _built(build)
        model, xml = compile_and_emit(assembly.mjspec, assembly.home, assembly.what, meshes=cache and meshes)
        return CompiledModel(model, Keyframe.of(model)), xml
    models = default_store()
    models.wait_for(key)
    stored = models.load_xml(key)
    if stored is not None:
        counts.hits += 1
        return None, stored
    answered = _on_miss(patched)
    if answered is not None:
        return answered
    assembly = _built(build)
    recorder = _recorder(assembly)
    model, xml = compile_and_emit(assembly.mjspec, assembly.home, assembly.what, meshes=meshes)
    if store:
        entry = models.entry(key)
        if entry is not None and not entry.xml and verify(entry.dependencies) is not None:
            models.add_xml(key, xml)  # the model it holds is this one: keep it, add the text
        else:
            models.save(key, model, recorder, assembly.label, xml)
    return CompiledModel(model, Keyframe.of(model)), xml
