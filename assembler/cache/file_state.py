"""One notion of a file's state and one content digest, for everything the cache keeps or checks.

A stored answer (a compiled model, a request record, a decoded mesh, a converted mesh, a robosuite
part file) is served only when every file it depends on is as it was, checked as git checks its
index: a file whose (size, mtime_ns, ctime_ns, inode) are unchanged is taken as unchanged, anything
else is hashed again and compared. The change time cannot be set back (``touch -r`` keeps the
modification time and size, not the change time), and a file replaced by another gets another
inode. A state taken while the file's times were too close to the moment it was recorded is
*racy*: a later write within the same clock tick could leave every field equal, so such a file is
always hashed again (git's rule), and the refreshed state is no longer racy.

A path is recorded with where it leads (``os.path.realpath``): a path through a symbolic link (the
file's own or one of its folders') is resolved again on every check, and leading elsewhere is a
change even when the new target's stat looks the same. A path without a link is not resolved again
(resolving costs a system call per folder of the path, 20 times the stat): whatever is put in its
place later, a link included, is another inode, so it is hashed again and compared.
"""

from __future__ import annotations

import os
import time
from collections.abc import Sequence
from dataclasses import dataclass, replace

import xxhash

from assembler.files.regular import open_regular

DIGEST = "xxh3_128"
"""The hash of every file content the cache compares. XXH3 rather than a cryptographic hash: it is
there to catch a changed or damaged file (any change of any byte), not a forger (a writer of the
cache folder could write anything), and it hashes a 44 MB model in a few milliseconds."""

GRANULARITY_NS = 2_000_000_000
"""How close to its recording a file's modification or change time makes its state racy. Two
seconds cover the coarsest file systems in use (FAT's 2 s) and MuJoCo's in-process asset cache,
which compares modification times in whole seconds."""

_CHUNK = 1 << 20

Stat = tuple[int, int, int, int]
"""(size, mtime_ns, ctime_ns, inode): what says a file is unchanged."""


def buffer_digest(data: object) -> str:
    """The :data:`DIGEST` of a buffer (bytes, a memory map, a numpy array), in hex."""
    return xxhash.xxh3_128(data).hexdigest()  # type: ignore[arg-type]


def file_digest(path: str | os.PathLike[str]) -> str:
    """The :data:`DIGEST` of a file's whole content, in hex; raises OSError."""
    digest = xxhash.xxh3_128()
    with open_regular(path) as stream:  # a FIFO put in a file's place: an error, not a wait
        while chunk := stream.read(_CHUNK):
            digest.update(chunk)
    return digest.hexdigest()


def stat_of(path: str | os.PathLike[str]) -> Stat:
    """The stat fields that say a file is unchanged (links followed); raises OSError."""
    stat = os.stat(path)
    return (stat.st_size, stat.st_mtime_ns, stat.st_ctime_ns, stat.st_ino)


def settled(stat: Stat, now_ns: int | None = None) -> bool:
    """True when the file was last modified at least :data:`GRANULARITY_NS` before ``now_ns``
    (default: now). A file modified more recently is not recorded at all: MuJoCo's in-process asset
    cache may still hold its previous content (it compares times in whole seconds)."""
    return stat[1] < (time.time_ns() if now_ns is None else now_ns) - GRANULARITY_NS


@dataclass(frozen=True)
class FileState:
    """One file as a stored answer saw it."""

    path: str
    """The path as it was used (links not resolved)."""

    target: str
    """Where ``path`` led (``os.path.realpath``): a re-pointed link is a change."""

    size: int
    mtime_ns: int
    ctime_ns: int
    inode: int

    digest: str
    """The :data:`DIGEST` of the content."""

    seen_ns: int
    """When the stat was taken: a stat too close to it is racy (see the module)."""

    @property
    def stat(self) -> Stat:
        """The stat fields of this state."""
        return (self.size, self.mtime_ns, self.ctime_ns, self.inode)

    @property
    def racy(self) -> bool:
        """True when the stat cannot vouch for the content: the file was modified or changed too
        near ``seen_ns``, so a write right after could have left every field as it is."""
        return max(self.mtime_ns, self.ctime_ns) >= self.seen_ns - GRANULARITY_NS


def state_of(path: str, digest: str | None = None, stat: Stat | None = None) -> FileState:
    """``path``'s state now, hashing it unless its ``digest`` (for the state ``stat``) is known;
    raises OSError, also when the file changes while it is hashed."""
    seen = time.time_ns()
    before = stat_of(path) if stat is None else stat
    found = digest if digest is not None else file_digest(path)
    if digest is None and stat_of(path) != before:
        raise OSError(f"{path} changed while it was read")
    size, mtime_ns, ctime_ns, inode = before
    return FileState(path, os.path.realpath(path), size, mtime_ns, ctime_ns, inode, found, seen)


def check(state: FileState) -> FileState | None:
    """``state`` itself when the file is unchanged and its stat vouches for it, a refreshed state
    when only its stat changed (the content hashed again is equal), None when it changed, moved
    elsewhere through a link or cannot be read."""
    try:
        # Only a path that led elsewhere is resolved again (a link on it may be re-pointed): for any
        # other, the file found there now is another inode if anything was put in its place.
        if state.target != state.path and os.path.realpath(state.path) != state.target:
            return None
        now = stat_of(state.path)
        if now == state.stat and not state.racy:
            return state
        if now[0] != state.size:
            return None
        fresh = state_of(state.path)
    except OSError:
        return None
    if fresh.digest != state.digest:
        return None
    return replace(fresh, digest=state.digest)


def check_all(states: Sequence[FileState]) -> list[FileState] | None:
    """Every state checked (see :func:`check`), or None at the first file that changed. An
    unchanged state comes back as the same object, so a caller can tell whether to write back."""
    current: list[FileState] = []
    for state in states:
        found = check(state)
        if found is None:
            return None
        current.append(found)
    return current
