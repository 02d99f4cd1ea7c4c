"""The files this process read to build what it writes: no output is ever written over one.

Every layer that reads an input of a build says so here (the compile path its MJCF, includes,
meshes and textures; a cache hit the files its entry was made from; the command line the spec
files), and the writer (:mod:`assembler.files.writing`) refuses a target that is one of them. Files
are known by device and inode, so another spelling of the path, a link to it or a hard link is the
same file.
"""

from __future__ import annotations

import os
from collections.abc import Iterable

_read: dict[tuple[int, int], str] = {}
"""(device, inode) -> the path it was read under."""

_written_as: dict[str, set[str]] = {}
"""A resolved path -> the paths, as written, that led to it through a symbolic link."""


def note_resolution(written: str | os.PathLike[str], resolved: str | os.PathLike[str]) -> None:
    """Remember that ``written`` (absolute, links not followed) led to ``resolved``: a record of
    what was read then keeps both, so a link re-pointed later is seen (:mod:`assembler.cache.file_state`)."""
    shown, target = os.path.abspath(written), os.fspath(resolved)
    if shown != target:
        _written_as.setdefault(target, set()).add(shown)


def written_as(resolved: str) -> set[str]:
    """The paths, as written, that led to ``resolved`` through a link (none when it was read directly)."""
    return _written_as.get(resolved, set())


def note_inputs(paths: Iterable[str | os.PathLike[str]]) -> None:
    """Remember ``paths`` as inputs of what this process builds (a path that cannot be read is skipped:
    the build will say so itself)."""
    for path in paths:
        try:
            stat = os.stat(path)
        except (OSError, ValueError):
            continue
        _read.setdefault((stat.st_dev, stat.st_ino), os.fspath(path))


def input_at(path: str | os.PathLike[str]) -> str | None:
    """The input ``path`` is (as it was read), or None when it is none of them."""
    try:
        stat = os.stat(path)
    except (OSError, ValueError):
        return None
    return _read.get((stat.st_dev, stat.st_ino))
