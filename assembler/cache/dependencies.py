"""The files a compiled model was made from, recorded by size, modification time and content.

A cache entry stores one :class:`Dependency` per file the compile read: each part's MJCF file,
the files it includes, and every mesh, height field, skin and texture file. On lookup a file whose
size and modification time are unchanged is taken as unchanged (as ``make`` and ccache do); one
whose stat differs is hashed again, so touching a mesh keeps the entry and editing it does not.
"""

from __future__ import annotations

import hashlib
import os
import time
from collections.abc import Callable, Iterable, Mapping, Sequence
from dataclasses import dataclass, replace

import mujoco

_CHUNK = 1 << 20

RECENT_NS = 2_000_000_000
"""Files modified this recently are not trusted: MuJoCo's in-process asset cache compares times in
whole seconds, so a compile may still see the previous content of a mesh edited within the same
second (ccache refuses too-new files for the same kind of reason)."""


KnownDigest = Callable[[str, os.stat_result], "str | None"]
"""A digest some other record already holds for a file in this exact state (the mesh store's)."""


@dataclass(frozen=True)
class Dependency:
    """One input file of a compile, as it was when the compile read it."""

    path: str
    size: int
    mtime_ns: int
    blake2b: str


def content_digest(path: str) -> str:
    """The file's BLAKE2b digest (hex)."""
    digest = hashlib.blake2b(digest_size=32)
    with open(path, "rb") as stream:
        while chunk := stream.read(_CHUNK):
            digest.update(chunk)
    return digest.hexdigest()


class Recorder:
    """Records the files of one compile: their stat before it and, afterwards (the store does it
    in its writer thread, off the caller's path), their digests and stat again. A file that
    changed in between, or shortly before, makes the record None, and the model is not stored:
    it may not match the files."""

    def __init__(
        self,
        paths: Iterable[str],
        read_earlier: Mapping[str, tuple[int, int]] | None = None,
        known: KnownDigest | None = None,
    ) -> None:
        """``read_earlier``: files already read before the compile (a part's MJCF and its includes,
        parsed when the part was made), with their stat from then: a change since then is a change.
        ``known``: where a file's digest may already be recorded (mesh files hashed by the mesh
        store), so the writer does not hash them again."""
        self._known = known
        self._recent = time.time_ns() - RECENT_NS
        self._stats: dict[str, tuple[int, int]] | None = dict(read_earlier or {})
        try:
            for path in sorted(set(paths) - set(self._stats)):
                stat = os.stat(path)
                self._stats[path] = (stat.st_size, stat.st_mtime_ns)
        except OSError:
            self._stats = None  # a missing file: the compile will say so

    def result(self) -> list[Dependency] | None:
        """The records; None if a file changed since the compile began or cannot be read."""
        if self._stats is None:
            return None
        records = []
        for path, (size, mtime_ns) in self._stats.items():
            try:
                digest = self._known(path, os.stat(path)) if self._known is not None else None
                digest = digest or content_digest(path)
                stat = os.stat(path)  # after hashing: a change while hashing shows here
            except OSError:
                return None
            if (stat.st_size, stat.st_mtime_ns) != (size, mtime_ns) or mtime_ns > self._recent:
                return None
            records.append(Dependency(path, size, mtime_ns, digest))
        return records


def verify(dependencies: Sequence[Dependency]) -> list[Dependency] | None:
    """The records refreshed to the files' current stat, or None when a file's content changed.

    A record comes back unchanged (the same object) when its file's stat is unchanged, so the
    caller can tell whether anything needs writing back.
    """
    current: list[Dependency] = []
    for dependency in dependencies:
        try:
            stat = os.stat(dependency.path)
            if stat.st_size == dependency.size and stat.st_mtime_ns == dependency.mtime_ns:
                current.append(dependency)
                continue
            if stat.st_size != dependency.size or content_digest(dependency.path) != dependency.blake2b:
                return None
        except OSError:
            return None
        current.append(replace(dependency, mtime_ns=stat.st_mtime_ns))
    return current


def asset_files(mjspec: mujoco.MjSpec) -> list[str]:
    """Every asset file a compile of ``mjspec`` reads: meshes, height fields, skins and textures
    (their paths are absolute in an assembly; see :mod:`assembler.mjcf.source`)."""
    files: list[str] = []
    for group in (mjspec.meshes, mjspec.hfields, mjspec.skins):
        files += [element.file for element in group if element.file]
    for texture in mjspec.textures:
        files += [file for file in (texture.file, *texture.cubefiles) if file]
    return files
