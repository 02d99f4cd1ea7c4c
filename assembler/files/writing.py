"""The one door for writing the user's files: atomically, with their usual permissions, only over
what may be replaced, every failure one line.

Every command and API that writes a user's file (``build -o`` and ``--bundle``, ``new``, ``scene``,
``experiment``, ``variants``, ``render``, ``RobotModel.save()``) writes through one function,
:func:`replace_file`; only the cache writes inside its own folder by itself (a test holds this).
A failed build must never leave a partial file or clobber the user's previous output, so every
file is written to a temporary file in the target folder and moved into place with one rename.
A file system error (no permission, disk full, a folder in the way, a name too long) is an
:class:`AssemblerError` naming the path; the old file, if any, is left as it was.

A target is replaced only when it is a regular file (or nothing): never a device, a FIFO, a socket
or a symbolic link (``-o /dev/full`` run as root would otherwise turn the device into a file), and
never a file this process read as an input of what it builds (:mod:`assembler.files.inputs`: the
spec, its MJCF and includes, meshes, the URDF), which the next build would need. Re-running a build
onto its own earlier output replaces that output, as it should.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import stat
import tempfile
from collections.abc import Callable, Iterator
from pathlib import Path
from typing import BinaryIO

from assembler.errors import AssemblerError
from assembler.files.inputs import input_at
from assembler.files.paths import display_path
from assembler.files.regular import kind_problem

TEMPORARY_NAME_STEM = 64
"""Characters of the target's name kept in its temporary file's name: any name legal for the
target (up to 255 bytes) then gives a legal temporary name too."""

SHOWN_PATH = 200
"""Characters of an over-long path shown in a message (its start and its end)."""


def _current_umask() -> int:
    mask = os.umask(0o022)  # reading the umask means setting it; put it back at once
    os.umask(mask)
    return mask


def _mode_for(path: Path) -> int:
    """An overwritten file keeps its permissions; a new one gets what ``open()`` would give it."""
    try:
        return path.stat().st_mode & 0o777
    except FileNotFoundError:
        return 0o666 & ~_current_umask()


def shown(path: Path) -> str:
    """The path for a message: as :func:`display_path` gives it, its middle cut when it is very long."""
    text = display_path(path)
    if len(text) <= SHOWN_PATH:
        return text
    half = SHOWN_PATH // 2
    return f"{text[:half]}...({len(text)} characters)...{text[-half:]}"


@contextlib.contextmanager
def cannot_write(path: Path) -> Iterator[None]:
    """Turn a file system error inside the block into one line naming ``path``."""
    try:
        yield
    except OSError as error:
        reason = error.strerror or str(error)
        if isinstance(error, (FileExistsError, NotADirectoryError)):  # mkdir where a file is
            reason = "a folder on its path is a file"
        raise AssemblerError(f"cannot write {shown(path)}: {reason}") from None


def check_target(path: Path) -> None:
    """Stop unless ``path`` may be replaced by an output: nothing is there, or a regular file that is
    no input of this process's build. A folder is left to the write itself (``Is a directory``)."""
    try:
        found = os.lstat(path)
    except (OSError, ValueError):
        return  # nothing there (or a path the write will report)
    if stat.S_ISLNK(found.st_mode):
        raise AssemblerError(
            f"cannot write {shown(path)}: it is a symbolic link (to {os.readlink(path)}); an output "
            "replaces only a regular file: remove the link or choose another path"
        )
    kind = None if stat.S_ISDIR(found.st_mode) else kind_problem(found.st_mode)
    if kind is not None:
        raise AssemblerError(
            f"cannot write {shown(path)}: {kind}; an output replaces only a regular file: choose another path"
        )
    source = input_at(path)
    if source is not None:
        raise AssemblerError(
            f"cannot write {shown(path)}: it is {display_path(source)}, an input of this build; writing "
            "there would destroy it: choose another path"
        )


def make_folder(path: Path) -> None:
    """Create ``path`` and its parents if needed; a failure is one line naming it."""
    with cannot_write(path):
        path.mkdir(parents=True, exist_ok=True)


@contextlib.contextmanager
def undone_on_failure(folder: Path) -> Iterator[list[Path]]:
    """Yield a list for the files the block creates; if the block fails, those files and the
    folders up to ``folder`` that did not exist before are removed (a failed bundle leaves nothing)."""
    missing = [parent for parent in (folder, *folder.parents) if not os.path.lexists(parent)]
    created: list[Path] = []
    try:
        yield created
    except BaseException:
        for path in created:
            with contextlib.suppress(OSError):
                path.unlink()
        for parent in missing:  # deepest first
            with contextlib.suppress(OSError):
                parent.rmdir()  # only if empty: never someone else's files
        raise


def _temporary(target: Path) -> tuple[int, str]:
    prefix = f".{target.name[:TEMPORARY_NAME_STEM]}."
    return tempfile.mkstemp(prefix=prefix, suffix=".tmp", dir=target.parent)


def replace_file(path: Path, fill: Callable[[BinaryIO], object]) -> None:
    """The door every write of a user's file goes through: ``fill(stream)`` writes the new content to
    a temporary file beside ``path``, which then replaces ``path`` with one rename, so readers see
    the old file or the whole new one, never half. :func:`check_target` is asked before and again
    just before the rename (something may have been put there meanwhile); a file system error is one
    line naming ``path``, and the old file, if any, is left as it was."""
    with cannot_write(path):
        check_target(path)
        path.parent.mkdir(parents=True, exist_ok=True)
        handle, temporary = _temporary(path)
        try:
            os.fchmod(handle, _mode_for(path))  # mkstemp makes 0600; users expect their usual permissions
            with os.fdopen(handle, "wb") as stream:
                fill(stream)
                stream.flush()
                os.fsync(stream.fileno())
            check_target(path)
            os.replace(temporary, path)
        except BaseException:
            Path(temporary).unlink(missing_ok=True)
            raise


def write_atomically(path: Path, content: str | bytes) -> None:
    """Write ``content`` to ``path`` through :func:`replace_file`."""
    data = content.encode() if isinstance(content, str) else content
    replace_file(path, lambda stream: stream.write(data))


def copy_atomically(source: Path, target: Path) -> None:
    """Copy ``source`` to ``target`` through :func:`replace_file` (a failure names ``target``)."""

    def fill(stream: BinaryIO) -> None:
        with open(source, "rb") as original:
            shutil.copyfileobj(original, stream)

    replace_file(target, fill)
