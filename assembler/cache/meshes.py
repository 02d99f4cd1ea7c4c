"""The mesh store: MuJoCo's decoding of each mesh file, kept by the file's content, so that no
process decodes the same OBJ or STL twice (the folder ``meshes/`` in the cache folder).

Two kinds of file, both small enough to write whole and move into place with one rename, so a
reader sees a whole file or none, whichever processes write at once:

- ``<size>-<key>.msh``, an entry: the ``.msh`` bytes (:mod:`assembler.cache.mesh_data`) behind a
  magic word and a BLAKE2b digest of the key and the bytes. The key is a digest of the source
  file's digest (:func:`assembler.cache.file_state.file_digest`), its decoder and MuJoCo's
  version: the same content anywhere on disk is one entry, and another MuJoCo decodes again. The
  source's size in the name lets a lookup skip hashing a file no entry can match (a new mesh). An entry that
  fails its digest (a flipped byte, a truncated write) is a miss and is removed, never a wrong
  mesh. An empty payload records a mesh without an exact ``.msh`` form: MuJoCo reads that file.
- ``<hash of path>.src``, a record: a file's digest with its size, modification and change times
  and inode, so a file whose stat is unchanged is not hashed again (ccache's rule; ctime cannot be
  set back, and a file modified in the last seconds gets no record). Records carry their own digest.

A hit touches both files, so their modification times order eviction: after each write the least
recently used go until the folder fits its bound. A folder that cannot be written (read-only,
disk full) means nothing is stored; no operation here raises OSError.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import re
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

import mujoco

from assembler.cache.file_state import Stat, file_digest, settled, stat_of
from assembler.cache.folder import GRACE_SECONDS, MESH_FILE
from assembler.cache.folder import evict as evict_folder
from assembler.files.cache_location import cache_dir, cache_disabled, max_bytes
from assembler.files.regular import open_regular, read_regular

FORMAT = 2
"""Version of the entry and record layout; part of every key."""

MAGIC = b"ASMMSH1\n"
CHECK_BYTES = 32
_ENTRY = re.compile(r"^(\d+)-[0-9a-f]{40}\.msh$")


def _check(*parts: bytes) -> bytes:
    digest = hashlib.blake2b(digest_size=CHECK_BYTES)
    for part in parts:
        digest.update(part)
    return digest.digest()


@dataclass(frozen=True)
class MeshStoreInfo:
    """Location, number of entries, bytes used and the bound."""

    directory: Path
    entries: int
    total_bytes: int
    max_bytes: int


class MeshStore:
    """Decoded meshes in ``directory``, at most ``max_bytes`` in all."""

    def __init__(self, directory: Path, max_bytes: int) -> None:
        self.directory = directory
        self.max_bytes = max_bytes

    @staticmethod
    def key(kind: str, digest: str) -> str:
        """The key of a file with content ``digest`` read by the decoder ``kind``."""
        text = f"{FORMAT}\0{mujoco.__version__}\0{sys.byteorder}\0{kind}\0{digest}"
        return hashlib.blake2b(text.encode(), digest_size=20).hexdigest()

    def sizes(self) -> set[int]:
        """The source sizes of the stored entries: a file of another size cannot be stored."""
        try:
            with os.scandir(self.directory) as entries:
                return {int(match[1]) for item in entries if (match := _ENTRY.match(item.name))}
        except OSError:
            return set()

    # ----- records: path -> digest ------------------------------------------------------

    def _record_name(self, path: str) -> str:
        return hashlib.blake2b(path.encode(), digest_size=20).hexdigest() + ".src"

    def recorded(self, path: str, stat: Stat) -> str | None:
        """The digest recorded for ``path`` if its stat is still ``stat``; None otherwise."""
        name = self._record_name(path)
        try:
            record = json.loads(read_regular(self.directory / name))
            fields = [record["path"], *record["stat"], record["digest"]]
            valid = record["check"] == _check(json.dumps(fields).encode()).hex()
        except (OSError, ValueError, KeyError, TypeError):
            return None
        if not valid:
            self._remove(name)
            return None
        if record["path"] != path or tuple(record["stat"]) != stat:
            return None
        self._touch(name)
        return str(record["digest"])

    def remember(self, path: str, stat: Stat, digest: str) -> None:
        """Record ``digest`` for ``path`` as it is now, if the file is settled."""
        if not settled(stat):
            return
        fields = [path, *stat, digest]
        record = {"path": path, "stat": list(stat), "digest": digest}
        record["check"] = _check(json.dumps(fields).encode()).hex()
        self._write(self._record_name(path), json.dumps(record).encode())

    def known_digest(self, path: str, stat: Stat) -> str | None:
        """The digest recorded for ``path`` in the state ``stat``, if any (no hashing)."""
        if not settled(stat):
            return None
        return self.recorded(path, stat)

    def digest(self, path: str) -> tuple[str, Stat] | None:
        """``path``'s digest and stat, from its record or by hashing it (and recording that);
        None when the file cannot be read or changes while it is hashed."""
        try:
            stat = stat_of(path)
            found = self.recorded(path, stat)
            if found is not None:
                return found, stat
            digest = file_digest(path)
            if stat_of(path) != stat:
                return None
        except OSError:
            return None
        self.remember(path, stat, digest)
        return digest, stat

    # ----- entries: key -> .msh bytes -----------------------------------------------------

    def get(self, kind: str, digest: str, size: int) -> bytes | None:
        """The stored ``.msh`` bytes of the ``size``-byte file with content ``digest`` (empty: it
        has no exact ``.msh`` form), or None on a miss. An entry that fails its check is removed."""
        key = self.key(kind, digest)
        name = f"{size}-{key}.msh"
        try:
            with open_regular(self.directory / name) as stream:
                head = stream.read(len(MAGIC) + CHECK_BYTES)
                payload = stream.read()
        except OSError:
            return None
        if head[: len(MAGIC)] != MAGIC or head[len(MAGIC) :] != _check(key.encode(), payload):
            self._remove(name)
            return None
        self._touch(name)
        return payload

    def has(self, kind: str, digest: str, size: int) -> bool:
        """True when an entry is stored (its check is left to :meth:`get`)."""
        return (self.directory / f"{size}-{self.key(kind, digest)}.msh").is_file()

    def put(self, kind: str, digest: str, size: int, payload: bytes) -> None:
        """Store ``payload`` for the ``size``-byte file with content ``digest``."""
        key = self.key(kind, digest)
        self._write(f"{size}-{key}.msh", MAGIC + _check(key.encode(), payload) + payload)

    def claim(self, kind: str, digest: str, size: int) -> Path | None:
        """Take the right to decode this file (None: another process holds it), so two processes
        seeing a new mesh at once do not both decode it. A claim older than GRACE_SECONDS is
        taken over: its holder died."""
        path = self.directory / f"{size}-{self.key(kind, digest)}.claim"
        for _ in range(2):
            try:
                self.directory.mkdir(parents=True, exist_ok=True)
                os.close(os.open(path, os.O_CREAT | os.O_EXCL | os.O_WRONLY, 0o644))
                return path
            except FileExistsError:
                with contextlib.suppress(OSError):
                    if time.time() - path.stat().st_mtime > GRACE_SECONDS:
                        path.unlink()
                        continue
                return None
            except OSError:
                return None
        return None

    # ----- files --------------------------------------------------------------------------

    def _write(self, name: str, content: bytes) -> None:
        """Write ``name`` whole or not at all; a folder that cannot be written is no error."""
        temporary = None
        try:
            self.directory.mkdir(parents=True, exist_ok=True)
            handle, temporary = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=self.directory)
            with os.fdopen(handle, "wb") as stream:
                stream.write(content)
            os.replace(temporary, self.directory / name)
        except OSError:
            if temporary is not None:
                with contextlib.suppress(OSError):
                    os.unlink(temporary)

    def _touch(self, name: str) -> None:
        """Mark a file used now (the clock's nanoseconds keep quick successive uses in order)."""
        now = time.time_ns()
        with contextlib.suppress(OSError):
            os.utime(self.directory / name, ns=(now, now))

    def _remove(self, *names: str) -> None:
        for name in names:
            with contextlib.suppress(OSError):
                (self.directory / name).unlink()

    def _files(self) -> list[tuple[int, str, int]]:
        """(last use in ns, name, size) of the store's own files; nothing else in the folder."""
        found = []
        try:
            with os.scandir(self.directory) as entries:
                for item in entries:
                    if MESH_FILE.match(item.name):
                        with contextlib.suppress(OSError):
                            stat = item.stat()
                            found.append((stat.st_mtime_ns, item.name, stat.st_size))
        except OSError:
            pass
        return found

    def evict(self) -> None:
        """Remove stale temporary files and claims, then the least recently used parts of the whole
        cache folder (this folder's parent, :mod:`assembler.cache.folder`) until it fits ``max_bytes``."""
        stale = time.time_ns() - int(GRACE_SECONDS * 1e9)
        for used, name, _ in self._files():
            if name.endswith((".tmp", ".claim")) and used < stale:
                self._remove(name)
        evict_folder(self.directory.parent, self.max_bytes)

    def info(self) -> MeshStoreInfo:
        """What the folder holds now."""
        files = self._files()
        entries = sum(1 for _, name, _ in files if name.endswith(".msh"))
        return MeshStoreInfo(self.directory, entries, sum(size for *_, size in files), self.max_bytes)

    def clear(self) -> MeshStoreInfo:
        """Remove every entry and record (only the store's own files); returns what was there."""
        before = self.info()
        self._remove(*(name for _, name, _ in self._files()))
        return before


def default_mesh_store() -> MeshStore | None:
    """The store the environment points at (``meshes/`` in the cache folder, under the cache's one
    bound), or None when the cache is off."""
    if cache_disabled():
        return None
    return MeshStore(cache_dir() / "meshes", max_bytes())
