"""The files a compiled model was made from, recorded as :class:`~assembler.cache.file_state.FileState`.

A cache entry stores one state per file the compile read: each part's MJCF file, the files it
includes, and every mesh, height field, skin and texture file. A lookup checks each as git checks
its index (:func:`~assembler.cache.file_state.check_all`): size, times and inode unchanged and not
racy, or hashed again and equal; a link re-pointed is a change.
"""

from __future__ import annotations

import os
import time
from collections.abc import Callable, Iterable, Mapping, Sequence

import mujoco

from assembler.cache.file_state import GRANULARITY_NS, FileState, Stat, check_all, stat_of, state_of
from assembler.files.inputs import written_as

Dependency = FileState
"""One input file of a compile, as it was when the compile read it."""

RECENT_NS = GRANULARITY_NS
"""Files modified this recently are not recorded: MuJoCo's in-process asset cache compares times in
whole seconds, so a compile may still see the previous content of a mesh edited within the same
second (ccache refuses too-new files for the same kind of reason)."""

KnownDigest = Callable[[str, Stat], "str | None"]
"""A digest some other record already holds for a file in this exact state (the mesh store's)."""


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
        parsed when the part was made), with their (size, mtime_ns) from then: a change since then
        is a change. ``known``: where a file's digest may already be recorded (mesh files hashed by
        the mesh store), so the writer does not hash them again."""
        self._known = known
        self._recent = time.time_ns() - RECENT_NS
        self._earlier = dict(read_earlier or {})
        self._stats: dict[str, Stat] | None = {}
        read = set(paths) | set(self._earlier)
        read |= {link for path in read for link in written_as(path)}  # links on the way, checked too
        try:
            for path in sorted(read):
                self._stats[path] = stat_of(path)
        except OSError:
            self._stats = None  # a missing file: the compile will say so

    def result(self) -> list[Dependency] | None:
        """The records; None if a file changed since the compile began or cannot be read."""
        if self._stats is None:
            return None
        records = []
        for path, stat in self._stats.items():
            earlier = self._earlier.get(path)
            if earlier is not None and earlier != stat[:2]:
                return None
            if stat[1] > self._recent:
                return None
            try:
                digest = self._known(path, stat) if self._known is not None else None
                state = state_of(path, digest, stat if digest is not None else None)
                if stat_of(path) != stat:  # after hashing: a change while hashing shows here
                    return None
            except OSError:
                return None
            records.append(state)
        return records


class SameFiles(Recorder):
    """The files of an entry already stored, given as a :class:`Recorder` gives a compile's: a model
    made from that entry's without a compile (a patched variant) was made from the same files. Its
    records are the entry's, checked again when the store writes (a change meanwhile: None)."""

    def __init__(self, dependencies: Sequence[Dependency]) -> None:
        self._dependencies = tuple(dependencies)

    def result(self) -> list[Dependency] | None:
        """The entry's records refreshed to the files' current state, or None when one changed."""
        return verify(self._dependencies)


def verify(dependencies: Sequence[Dependency]) -> list[Dependency] | None:
    """The records refreshed to the files' current state, or None when a file changed (see
    :func:`~assembler.cache.file_state.check_all`)."""
    return check_all(dependencies)


def asset_files(mjspec: mujoco.MjSpec) -> list[str]:
    """Every asset file a compile of ``mjspec`` reads: meshes, height fields, skins and textures
    (their paths are absolute in an assembly; see :mod:`assembler.mjcf.source`)."""
    files: list[str] = []
    for group in (mjspec.meshes, mjspec.hfields, mjspec.skins):
        files += [element.file for element in group if element.file]
    for texture in mjspec.textures:
        files += [file for file in (texture.file, *texture.cubefiles) if file]
    return [os.fspath(file) for file in files]
