"""The cache folder: one manifest and one model file per entry (and the emitted XML, once asked
for), written atomically, bounded in size with least-recently-used eviction, safe with several
processes at once.

There is no shared index that a crash or a race could corrupt: the folder is the index. Every
file is written under a temporary name in the same folder and moved into place with one rename,
so a reader sees a whole file or none; a writer killed mid-write leaves only a temporary file,
removed by a later clean-up once it is old. A lookup touches the manifest, so its modification
time is the entry's last use, and eviction (after each write) drops the least recently used
entries until the folder fits the limit. Two processes filling one entry each write their own
model file and the last manifest wins; the other model file becomes an orphan and is removed.
Anything unreadable (a truncated manifest, a model or XML file whose size or content digest
differs from its manifest's) is a miss and is removed, never an error and never a wrong model.
"""

from __future__ import annotations

import contextlib
import json
import mmap
import os
import secrets
import tempfile
import threading
import time
from collections.abc import Mapping
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.cache.dependencies import Dependency, Recorder, SameFiles, verify
from assembler.cache.entry import MANIFEST_SUFFIX, MODEL_SUFFIX, XML_SUFFIX, Entry
from assembler.cache.file_state import buffer_digest
from assembler.cache.folder import GRACE_SECONDS, MODEL_FILE
from assembler.cache.folder import evict as evict_folder
from assembler.cache.key import FORMAT
from assembler.files.inputs import note_inputs
from assembler.files.regular import open_regular, read_regular
from assembler.mjcf import installed_mujoco

TEMP_SUFFIX = ".tmp"

PATCH_SUFFIX = ".patch"
"""A patch kept in place of a model (:meth:`ModelStore.save_patch`)."""


_writers: list[threading.Thread] = []
_pending: dict[tuple[str, str], threading.Thread] = {}
"""(folder, key) -> the thread writing that entry: a lookup of it in this process waits for it."""


def wait_for_writes() -> None:
    """Block until every entry this process started writing is in place (tests, benchmarks)."""
    while _writers:
        _writers.pop().join()


@dataclass(frozen=True)
class CacheInfo:
    """What ``assembler cache info`` prints."""

    directory: Path
    entries: int
    total_bytes: int
    max_bytes: int
    problem: str = ""
    """Why models cannot be stored there (the folder is a file, is read-only, ...); empty when usable."""

    not_removed: tuple[str, ...] = ()
    """After ``clear``: the files that could not be removed, each with the reason."""


def usability_problem(directory: Path) -> str:
    """Why the cache cannot keep models in ``directory``, or "" when it can (made when first needed)."""
    existing = directory
    while not existing.exists():
        if existing.parent == existing:
            return "no part of its path exists"
        existing = existing.parent
    if not existing.is_dir():
        return f"{existing} is a file, not a folder"
    if not os.access(existing, os.W_OK | os.X_OK):
        return f"{existing} is read-only for this user: models are compiled every time"
    return ""


def _descriptor_path(descriptor: int, fallback: Path) -> str:
    """A path naming the open file itself, so eviction by another process cannot pull it away
    between our checks and MuJoCo's read (and MuJoCo never logs a failed open)."""
    for folder in ("/proc/self/fd", "/dev/fd"):
        if os.path.isdir(folder):
            return f"{folder}/{descriptor}"
    return str(fallback)


class ModelStore:
    """Compiled models in ``directory``, at most ``max_bytes`` in all."""

    def __init__(self, directory: Path, max_bytes: int) -> None:
        self.directory = directory
        self.max_bytes = max_bytes

    # ----- lookup -------------------------------------------------------------------------

    def wait_for(self, key: str) -> None:
        """Wait until this process's write of the entry ``key``, if one is under way, is done:
        the entry just compiled is then found rather than compiled again."""
        writer = _pending.get((str(self.directory), key))
        if writer is not None:
            writer.join()

    def _read_entry(self, key: str) -> Entry | None:
        try:
            text = read_regular(self.directory / (key + MANIFEST_SUFFIX)).decode("utf-8")
        except (OSError, UnicodeDecodeError):
            return None
        try:
            entry = Entry.from_json(text)
        except ValueError:
            self._remove(key + MANIFEST_SUFFIX)
            return None
        return entry if entry.key == key else None

    def entry(self, key: str) -> Entry | None:
        """The manifest stored under ``key``, unchecked (its files may have changed)."""
        return self._read_entry(key)

    def _open_model(self, entry: Entry) -> mujoco.MjModel | None:
        """The entry's model, if its file is whole: its exact size and content digest, and MuJoCo
        loads it without a warning. MuJoCo never sees a file whose digest differs."""
        path = self.directory / entry.model
        try:
            with open_regular(path) as stream:  # a FIFO planted there is a miss, not a wait
                if os.fstat(stream.fileno()).st_size != entry.model_bytes:
                    return None
                with mmap.mmap(stream.fileno(), 0, access=mmap.ACCESS_READ) as content:
                    if buffer_digest(content) != entry.digest:
                        return None
                with installed_mujoco.collected() as warned:
                    model = mujoco.MjModel.from_binary_path(_descriptor_path(stream.fileno(), path))
                return None if warned else model
        except (OSError, ValueError):
            return None

    def load(self, key: str) -> tuple[mujoco.MjModel, tuple[Dependency, ...]] | None:
        """The model stored under ``key`` and its files, if every one of them is unchanged."""
        entry = self._read_entry(key)
        if entry is None:
            return None
        current = verify(entry.dependencies)
        if current is None:
            return None  # an input changed: the caller compiles and replaces the entry
        note_inputs(state.path for state in current)
        model = self._open_model(entry)
        if model is None:
            self._discard(entry)
            return None
        refreshed = any(new is not old for new, old in zip(current, entry.dependencies, strict=True))
        with contextlib.suppress(OSError):
            if refreshed:  # touched but unchanged files: record their new stat, so we hash them once
                self._write(entry.manifest, replace(entry, dependencies=tuple(current)))
            self._touch(entry.manifest)
        return model, tuple(current)

    def load_xml(self, key: str) -> str | None:
        """The XML stored with the entry ``key``, if the entry has one, every file it was compiled
        from is unchanged and the XML file is whole (else it is removed: a miss). The model file
        is not read: the XML does not need it."""
        entry = self._read_entry(key)
        current = verify(entry.dependencies) if entry is not None and entry.xml else None
        if entry is None or current is None:
            return None
        note_inputs(state.path for state in current)
        try:
            data = read_regular(self.directory / entry.xml)
            if len(data) == entry.xml_bytes and buffer_digest(data) == entry.xml_digest:
                with contextlib.suppress(OSError):
                    self._touch(entry.manifest)
                return data.decode("utf-8")
        except (OSError, UnicodeDecodeError):
            pass
        self._drop_xml(entry)
        return None

    def _drop_xml(self, entry: Entry) -> None:
        """Forget a broken XML file: the manifest keeps its model, without the XML."""
        latest = self._read_entry(entry.key)
        if latest is not None and latest.xml == entry.xml:
            with contextlib.suppress(OSError):
                self._write(entry.manifest, replace(latest, xml="", xml_bytes=0, xml_digest=""))
        self._remove(entry.xml)

    def add_xml(self, key: str, xml: str) -> None:
        """Keep ``xml`` with the entry ``key`` (written by an earlier compile), if it is there; a
        cache that cannot be written only means the XML is emitted again next time."""
        entry = self._read_entry(key)
        if entry is None or entry.xml:
            return
        data = xml.encode("utf-8")
        name = f"{key}-{secrets.token_hex(6)}{XML_SUFFIX}"
        try:
            self._write(name, data)
            latest = self._read_entry(key)
            if latest is None or latest.model != entry.model or latest.xml:
                self._remove(name)  # replaced meanwhile by another process: its entry stands
                return
            self._write(entry.manifest, _with_xml(latest, name, data))
        except OSError:
            self._remove(name)

    def _discard(self, entry: Entry) -> None:
        """Remove a broken entry; its manifest only if no other process has replaced it since."""
        latest = self._read_entry(entry.key)
        if latest is not None and latest.model == entry.model:
            self._remove(entry.manifest)
        self._remove(entry.model, entry.xml)

    def _touch(self, name: str) -> None:
        """Mark an entry used now. The clock's nanoseconds, not the file system's coarser tick
        (a few milliseconds), so uses in quick succession keep their order."""
        now = time.time_ns()
        os.utime(self.directory / name, ns=(now, now))

    # ----- writing ------------------------------------------------------------------------

    def _write(self, name: str, content: Entry | NDArray[np.uint8] | bytes) -> None:
        self.directory.mkdir(parents=True, exist_ok=True)
        handle, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=TEMP_SUFFIX, dir=self.directory)
        try:
            with os.fdopen(handle, "wb") as stream:
                if isinstance(content, Entry):
                    stream.write(content.to_json().encode())
                else:
                    stream.write(content if isinstance(content, bytes) else content.data)
            os.replace(temporary, self.directory / name)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise

    def save(
        self, key: str, model: mujoco.MjModel, recorder: Recorder, label: str, xml: str | None = None
    ) -> None:
        """Store ``model`` (and its emitted ``xml``, when given) under ``key``, replacing an older
        entry, then evict down to the limit.

        The model is serialised now (the caller may change it next); hashing its input files and
        writing the entry happen in a background thread, so a cold load costs little more than
        the compile. The interpreter waits for that thread at exit. An input that changed meanwhile
        means nothing is stored; a cache that cannot be written (read-only, disk full) only means
        no caching: never an error.
        """
        buffer = np.empty(mujoco.mj_sizeModel(model), dtype=np.uint8)
        mujoco.mj_saveModel(model, None, buffer)
        entry = Entry(
            key=key,
            model=f"{key}-{secrets.token_hex(6)}{MODEL_SUFFIX}",
            model_bytes=buffer.size,
            digest=buffer_digest(buffer),
            label=label,
            dependencies=(),
        )
        text = xml.encode("utf-8") if xml is not None else None
        if text is not None:
            entry = _with_xml(entry, f"{key}-{secrets.token_hex(6)}{XML_SUFFIX}", text)
        writer = threading.Thread(
            target=self._commit, args=(entry, buffer, recorder, text), name="assembler-cache-writer"
        )
        _writers.append(writer)
        _pending[(str(self.directory), key)] = writer
        writer.start()

    def save_patched(self, key: str, model: mujoco.MjModel, label: str, xml: str, source: str) -> None:
        """Store ``model`` and its ``xml``, made from the entry ``source``'s without a compile (a
        patched variant written to a file), under ``key`` with ``source``'s files as its own: the
        same request is then answered from the cache as a compiled one is. Nothing is stored when
        ``source`` is gone."""
        found = self._read_entry(source)
        if found is not None:
            self.save(key, model, SameFiles(found.dependencies), label, xml)

    def _commit(self, entry: Entry, buffer: NDArray[np.uint8], recorder: Recorder, xml: bytes | None) -> None:
        try:
            self._commit_now(entry, buffer, recorder, xml)
        finally:
            _pending.pop((str(self.directory), entry.key), None)

    def _commit_now(
        self, entry: Entry, buffer: NDArray[np.uint8], recorder: Recorder, xml: bytes | None
    ) -> None:
        dependencies = recorder.result()
        if dependencies is None:
            return
        entry = replace(entry, dependencies=tuple(dependencies))
        key = entry.key
        current = self._read_entry(key)
        if current is not None and current.xml and not entry.xml and verify(current.dependencies) is not None:
            return  # the same model from the same files, with its XML already: keep that one
        try:
            self._write(entry.model, buffer)
            if xml is not None:
                self._write(entry.xml, xml)
            previous = self._read_entry(key)
            self._write(entry.manifest, entry)
            self._touch(entry.manifest)
        except OSError:
            self._remove(entry.model, entry.xml)
            return
        if previous is not None and previous.model != entry.model:
            self._remove(previous.model)
        if previous is not None and previous.xml != entry.xml:
            self._remove(previous.xml)
        self.evict()

    # ----- patches ------------------------------------------------------------------------

    def save_patch(self, key: str, source: str, patch: Mapping[str, Any]) -> None:
        """Keep under ``key``, in place of a model file, how its model is made from the entry
        ``source``'s without a compile (a patched variant, :mod:`assembler.patch.derived`): a few
        hundred bytes of JSON where a model file holds megabytes of meshes. Nothing of it needs
        checking but the source entry, whose files are checked when it is loaded. A cache that
        cannot be written only means the patch is worked out again next time."""
        text = json.dumps({"format": FORMAT, "key": key, "source": source, "patch": patch}, allow_nan=False)
        with contextlib.suppress(OSError):
            self._write(key + PATCH_SUFFIX, text.encode("utf-8"))

    def load_patch(self, key: str) -> tuple[str, Mapping[str, Any]] | None:
        """The source entry and the patch kept under ``key`` (see :meth:`save_patch`), or None; a
        file that is not a whole patch of this format is removed."""
        name = key + PATCH_SUFFIX
        try:
            data = json.loads(read_regular(self.directory / name).decode("utf-8"))
        except (OSError, UnicodeDecodeError):
            return None
        except ValueError:
            data = None
        whole = isinstance(data, dict) and data.get("format") == FORMAT and data.get("key") == key
        if not whole or not isinstance(data.get("source"), str) or not isinstance(data.get("patch"), dict):
            self._remove(name)
            return None
        with contextlib.suppress(OSError):
            self._touch(name)
        return data["source"], data["patch"]

    # ----- housekeeping -------------------------------------------------------------------

    def _remove(self, *names: str) -> None:
        for name in filter(None, names):
            with contextlib.suppress(OSError):
                (self.directory / name).unlink()

    def _files(self) -> list[os.DirEntry[str]]:
        """The cache's own files: eviction and ``clear`` never touch anything else in the folder."""
        try:
            with os.scandir(self.directory) as entries:
                return [e for e in entries if MODEL_FILE.match(e.name) and e.is_file()]
        except OSError:
            return []

    def evict(self) -> None:
        """Remove stale temporary files and orphaned models, then the least recently used parts of
        the whole cache folder (:mod:`assembler.cache.folder`) until it fits in ``max_bytes``."""
        now = time.time()
        referenced: set[str] = set()
        others: list[tuple[str, float]] = []
        for item in self._files():
            with contextlib.suppress(OSError):
                if item.name.endswith(MANIFEST_SUFFIX):
                    entry = self._read_entry(item.name.removesuffix(MANIFEST_SUFFIX))
                    referenced.update((entry.model, entry.xml) if entry is not None else ())
                elif not item.name.endswith(PATCH_SUFFIX):  # a patch stands alone: never an orphan
                    others.append((item.name, item.stat().st_mtime))
        for name, mtime in others:
            if name not in referenced and now - mtime > GRACE_SECONDS:
                self._remove(name)
        evict_folder(self.directory, self.max_bytes)

    def info(self) -> CacheInfo:
        """Location, number of entries, bytes used and the limit."""
        files = self._files()
        total = 0
        for item in files:
            with contextlib.suppress(OSError):
                total += item.stat().st_size
        entries = sum(1 for item in files if item.name.endswith(MANIFEST_SUFFIX))
        return CacheInfo(self.directory, entries, total, self.max_bytes, usability_problem(self.directory))

    def clear(self) -> CacheInfo:
        """Remove every entry (only the cache's own files); returns what was there, and the files
        that could not be removed with why."""
        before = self.info()
        failed: list[str] = []
        for item in self._files():
            try:
                (self.directory / item.name).unlink()
            except FileNotFoundError:
                continue  # another process removed it meanwhile
            except OSError as error:
                failed.append(f"{item.name}: {error.strerror}")
        return replace(before, not_removed=tuple(failed))


def _with_xml(entry: Entry, name: str, data: bytes) -> Entry:
    """``entry`` naming ``name`` as its XML file, whose content is ``data``."""
    return replace(entry, xml=name, xml_bytes=len(data), xml_digest=buffer_digest(data))
