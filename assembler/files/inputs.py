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
        try:
            where = os.path.abspath(path)  # looked at again later, maybe from another working folder
        except OSError:  # the working folder is gone
            where = os.fspath(path)
        _read.setdefault((stat.st_dev, stat.st_ino), where)


def input_at(path: str | os.PathLike[str]) -> str | None:
    """The input ``path`` is (as it was read), or None when it is none of them. The input must still
    be there under the path it was read by: an inode freed by a deleted input and given to a new file
    is not that input (a long process, a test session, reads and deletes many files)."""
    try:
        stat = os.stat(path)
    except (OSError, ValueError):
        return None
    key = (stat.st_dev, stat.st_ino)
    read_as = _read.get(key)
    if read_as is None:
        return None
    try:
        again = os.stat(read_as)
    except (OSError, ValueError):
        return None
    return read_as if (again.st_dev, again.st_ino) == key else None
