"""Files named by their content, verified on every use: converted meshes and robosuite's part files.

Some stored files must be read by something else as files (MuJoCo reads an OBJ converted from
COLLADA; robosuite reads the MJCF of each part), so they cannot be checked as they are read. Each
is named ``<prefix>-<digest><suffix>``, the digest (:data:`~assembler.cache.file_state.DIGEST`) of
its own content, and is hashed again whenever it is handed out: a file edited or damaged in the
cache folder is removed and made again, never served. A use sets the file's access time and keeps
its modification time: a converted mesh is itself an input of the compiled models made from it, and
its modification time is what says when it was made; eviction orders these files by their last use,
the later of the two times (:mod:`assembler.cache.folder`), so a file in use is not the first to go.
Files are written whole under a temporary name and moved into place with one rename, so two
processes making one file agree on it.

With the cache off (``--no-cache``, ``ASSEMBLER_NO_CACHE``) or its folder unwritable, the files go
to a folder of the process's own (:func:`~assembler.files.cache_location.scratch_dir`): nothing is read
from the cache.
"""

from __future__ import annotations

import contextlib
import json
import os
import re
import tempfile
import time
from collections.abc import Callable, Iterable, Mapping
from dataclasses import asdict
from pathlib import Path

from assembler.cache.dependencies import Recorder
from assembler.cache.file_state import FileState, buffer_digest, check_all, file_digest
from assembler.files.cache_location import cache_dir, cache_disabled, scratch_dir
from assembler.files.regular import read_regular

CONVERTED = "converted-meshes"
"""Meshes converted to OBJ (and renamed copies), below the cache folder."""

PARTS = "robosuite"
"""Robosuite's part files, below the cache folder."""

TEMP_SUFFIX = ".tmp"

_NAME = re.compile(r"^(?P<prefix>.+)-(?P<digest>[0-9a-f]{32})(?P<suffix>\.[A-Za-z0-9]+)$")


def content_folder(kind: str) -> Path:
    """The folder of ``kind`` (:data:`CONVERTED`, :data:`PARTS`): in the cache folder when the cache
    is on and writable, else in this process's scratch folder."""
    if not cache_disabled():
        folder = cache_dir() / kind
        with contextlib.suppress(OSError):
            folder.mkdir(parents=True, exist_ok=True)
            if os.access(folder, os.W_OK | os.X_OK):
                return folder
    folder = scratch_dir() / kind
    folder.mkdir(parents=True, exist_ok=True)
    return folder


def _whole(path: Path) -> bool:
    """True when ``path``'s content has the digest its name says (else it is removed)."""
    match = _NAME.match(path.name)
    try:
        if match is not None and file_digest(path) == match["digest"]:
            return True
    except OSError:
        return False
    with contextlib.suppress(OSError):
        path.unlink()
    return False


def _used(path: Path) -> Path:
    """``path``, its use recorded in its access time (its modification time kept) for eviction."""
    with contextlib.suppress(OSError):  # a read-only cache folder is still served; it is not evicted from
        os.utime(path, ns=(time.time_ns(), path.stat().st_mtime_ns))
    return path


def _temporary(folder: Path, suffix: str) -> Path:
    handle, name = tempfile.mkstemp(dir=folder, prefix=".", suffix=suffix + TEMP_SUFFIX)
    os.close(handle)
    return Path(name)


def kept_file(folder: Path, prefix: str, suffix: str, make: Callable[[str], object]) -> Path:
    """The verified file ``prefix-<digest>suffix`` in ``folder``; when none is whole, ``make(path)``
    writes a new one to a temporary path, which is then named by its digest. ``prefix`` names what
    the file was made from (a source's stem and digest), so one source finds its file again."""
    for found in sorted(folder.glob(f"{glob_escape(prefix)}-*{suffix}")):
        match = _NAME.match(found.name)
        if match is not None and match["prefix"] == prefix and _whole(found):
            return _used(found)
    temporary = _temporary(folder, suffix)
    try:
        make(str(temporary))
        target = folder / f"{prefix}-{file_digest(temporary)}{suffix}"
        os.replace(temporary, target)
    finally:
        temporary.unlink(missing_ok=True)
    return target


def text_file(folder: Path, text: str, suffix: str) -> Path:
    """A verified file in ``folder`` holding ``text``, named by its digest; written only when no
    whole one is there (a warm run writes nothing)."""
    data = text.encode("utf-8")
    target = folder / f"text-{buffer_digest(data)}{suffix}"
    if target.exists() and _whole(target):
        return _used(target)
    _write_whole(target, data)
    return target


def glob_escape(text: str) -> str:
    """``text`` with the characters ``glob`` treats as patterns escaped."""
    return re.sub(r"([*?\[])", r"[\1]", text)


def _write_whole(target: Path, data: bytes) -> None:
    temporary = _temporary(target.parent, target.suffix)
    try:
        temporary.write_bytes(data)
        os.replace(temporary, target)
    finally:
        temporary.unlink(missing_ok=True)


def recorded_text_file(
    folder: Path,
    key: str,
    read: Iterable[str],
    emit: Callable[[], str],
    suffix: str,
    read_earlier: Callable[[], Mapping[str, tuple[int, int]]] | None = None,
) -> Path:
    """The file of the text ``emit()`` makes for ``key`` (a digest of everything that decides the
    text but the files it reads), kept across processes: when the record of ``key`` finds every file
    in ``read`` unchanged (:func:`~assembler.cache.file_state.check_all`) and its text file whole,
    nothing is emitted or written. Otherwise the text is emitted, written (:func:`text_file`) and
    recorded with the files' states; a file changed meanwhile means no record. ``read`` is consumed
    only then, before ``read_earlier()``: files read before the emission (a part's MJCF, parsed when
    the part was made) with their (size, mtime_ns) then, a change since then being a change."""
    record = folder / f"record-{key}.json"
    with contextlib.suppress(OSError, ValueError, KeyError, TypeError):
        data = json.loads(read_regular(record).decode("utf-8"))
        states = [FileState(**state) for state in data["read"]]
        target = folder / str(data["file"])
        if target.parent == folder and check_all(states) is not None and target.exists() and _whole(target):
            return _used(target)
    files = list(read)
    recorder = Recorder(files, read_earlier() if read_earlier is not None else None)
    target = text_file(folder, emit(), suffix)
    recorded = recorder.result()
    if recorded is not None:
        text = json.dumps({"file": target.name, "read": [asdict(state) for state in recorded]})
        with contextlib.suppress(OSError):
            _write_whole(record, text.encode("utf-8"))
    return target
