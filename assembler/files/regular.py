"""Reading only regular files: what a path is when it is not one, said in one line.

A spec, MJCF, URDF, mesh or cache file is read from a regular file only. Opening a FIFO blocks
until someone writes to it (a FIFO planted in a spec folder or in the cache would hang the
process), a device streams without end (``/dev/zero``) or nothing (``/dev/null``, read as an
empty spec), and a folder is no file. So every reader opens through :func:`open_regular`, which
never blocks, checks the open file itself (no race with a swap after a check) and raises
:class:`NotARegularFile`, an :class:`OSError` whose ``strerror`` says what the path is, e.g.
``it is a FIFO (named pipe), not a regular file``; readers print ``strerror`` as they would for a
missing file. A file from a stranger is read with a limit (:func:`read_bounded`): at most one byte
more than its reader allows, so a file of any size costs no more than the limit.
"""

from __future__ import annotations

import errno
import os
import stat
from typing import BinaryIO

_KINDS = (
    (stat.S_ISDIR, "it is a folder, not a file"),
    (stat.S_ISFIFO, "it is a FIFO (named pipe), not a regular file"),
    (stat.S_ISCHR, "it is a character device, not a regular file"),
    (stat.S_ISBLK, "it is a block device, not a regular file"),
    (stat.S_ISSOCK, "it is a socket, not a regular file"),
)


class NotARegularFile(OSError):
    """The path exists and is not a regular file (``strerror`` says what it is)."""


def kind_problem(mode: int) -> str | None:
    """What a file of ``mode`` is when not a regular file (``it is a folder, not a file``), else None."""
    for test, text in _KINDS:
        if test(mode):
            return text
    return None if stat.S_ISREG(mode) else "it is not a regular file"


def not_regular(path: str | os.PathLike[str]) -> str | None:
    """What ``path`` is when it exists and is not a regular file (links followed), else None (a
    regular file, or nothing there: the reader says so itself)."""
    try:
        mode = os.stat(path).st_mode
    except (OSError, ValueError):
        return None
    return kind_problem(mode)


def open_regular(path: str | os.PathLike[str]) -> BinaryIO:
    """``path`` opened for reading in binary, if it is a regular file; :class:`NotARegularFile`
    (never a wait) when it is a FIFO, a device, a socket or a folder, other :class:`OSError` as
    ``open`` raises them."""
    handle = os.open(path, os.O_RDONLY | os.O_NONBLOCK | getattr(os, "O_CLOEXEC", 0))
    try:
        problem = kind_problem(os.fstat(handle).st_mode)
        if problem is not None:
            raise NotARegularFile(errno.EINVAL, problem, os.fspath(path))
        os.set_blocking(handle, True)
        return os.fdopen(handle, "rb")
    except BaseException:
        os.close(handle)
        raise


def read_regular(path: str | os.PathLike[str]) -> bytes:
    """The whole content of the regular file ``path`` (:func:`open_regular`'s refusals), for files
    of known, bounded size such as the cache's own."""
    with open_regular(path) as stream:
        return stream.read()


class FileTooLarge(OSError):
    """The regular file holds more bytes than its reader allows (``limit``)."""

    def __init__(self, path: str | os.PathLike[str], limit: int) -> None:
        super().__init__(errno.EFBIG, f"the file's size exceeds the limit of {limit} bytes", os.fspath(path))
        self.limit = limit


def read_bounded(path: str | os.PathLike[str], limit: int) -> bytes:
    """The content of the regular file ``path`` (:func:`open_regular`'s refusals), at most ``limit``
    bytes: :class:`FileTooLarge` when it holds more (only ``limit + 1`` bytes are read to know)."""
    with open_regular(path) as stream:
        data = stream.read(limit + 1)
    if len(data) > limit:
        raise FileTooLarge(path, limit)
    return data
