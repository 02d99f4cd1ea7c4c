"""The cache folder as one store: one size bound, one eviction, one ``clear`` and one ``info`` over
every part it holds.

::

    <cache folder>/                 compiled models: <key>.json manifests, <key>-<id>.mjb/.xml files
    <cache folder>/meshes/          decoded meshes (.msh) and source records (.src)
    <cache folder>/requests/        request records
    <cache folder>/converted-meshes/  meshes converted to OBJ, named by their content
    <cache folder>/robosuite/       robosuite's part files, named by their content

Each part's file names are known here, and nothing else in the folder is ever counted, evicted or
removed. A unit of eviction is what goes together (a model's manifest with its model and XML
files; any other file alone); its last use is its modification time, which every hit sets. After
every write of a model or a decoded mesh (a request record is too small to matter: its own store
bounds their number), temporary files and claims older than :data:`GRACE_SECONDS` (their writer
died) are removed, then the least recently used units until everything fits
``ASSEMBLER_CACHE_MAX_BYTES``.
Files named by their content (converted meshes, robosuite's part files) keep their modification
time (when they were made: a model made from a converted mesh records it) and mark a use in their
access time instead (:mod:`assembler.cache.content`): their last use is the later of the two, and
one used in the last :data:`IN_USE_SECONDS` is not evicted (a build may be about to read it).
"""

from __future__ import annotations

import contextlib
import os
import re
import time
from dataclasses import dataclass, field
from pathlib import Path

GRACE_SECONDS = 600.0
"""A temporary file or claim younger than this may belong to a writer still at work."""

IN_USE_SECONDS = 60.0
"""A file named by its content used this recently may have just been handed to a build by its path
(a converted mesh MuJoCo is about to read, a part file robosuite is about to parse): it is not
evicted, though the folder may then stay above its bound for as long."""

MODEL_FILE = re.compile(r"^\.?(?P<key>[0-9a-f]{40})(-[0-9a-f]{12}\.(mjb|xml)|\.json|\.patch)(\.\w+\.tmp)?$")
"""Model manifests, model and XML files, patches and their temporary files (:mod:`assembler.cache.store`)."""

MESH_FILE = re.compile(r"^\.?(\d+-[0-9a-f]{40}\.(msh|claim)|[0-9a-f]{40}\.src)(\.\w+\.tmp)?$")
"""Decoded meshes, claims, source records and their temporary files (:mod:`assembler.cache.meshes`)."""

REQUEST_FILE = re.compile(r"^\.?[0-9a-f]{40}\.(json|[\w.]+\.tmp)$")
"""Request records and their temporary files (:mod:`assembler.cache.requests`)."""

CONTENT_FILE = re.compile(r"^\.?[^/]+-[0-9a-f]{32}\.[A-Za-z0-9]+$|^\.[^/]+\.tmp$")
"""Files named by their content and their temporary files (:mod:`assembler.cache.content`)."""

PARTS: dict[str, re.Pattern[str]] = {
    "": MODEL_FILE,
    "meshes": MESH_FILE,
    "requests": REQUEST_FILE,
    "converted-meshes": CONTENT_FILE,
    "robosuite": CONTENT_FILE,
}
"""Each part's folder (below the cache folder) and the names of its files."""

LABELS = {
    "": "models",
    "meshes": "decoded meshes",
    "requests": "request records",
    "converted-meshes": "converted meshes",
    "robosuite": "robosuite part files",
}
"""What ``cache info`` calls each part."""


def _pending(name: str) -> bool:
    """A file a writer may still be working on: a temporary file or a claim."""
    return name.endswith((".tmp", ".claim"))


@dataclass
class PartInfo:
    """One part of the store: its files (temporary ones included) and their bytes."""

    files: int = 0
    total_bytes: int = 0


@dataclass
class FolderInfo:
    """What the whole store holds."""

    directory: Path
    parts: dict[str, PartInfo] = field(default_factory=dict)
    not_removed: list[str] = field(default_factory=list)
    """After :func:`clear`: the files that could not be removed, each with the reason."""

    @property
    def total_bytes(self) -> int:
        """Bytes of every part."""
        return sum(part.total_bytes for part in self.parts.values())


@dataclass
class _Unit:
    last_use_ns: int
    size: int
    paths: list[Path]
    used_ns: int = 0
    """The manifest's time, for a model (its files' times say only when they were written)."""

    @property
    def last_use(self) -> int:
        return self.used_ns or self.last_use_ns


def _scan(root: Path) -> list[tuple[str, os.DirEntry[str], os.stat_result]]:
    """(part, entry, stat) of every file of every part."""
    found = []
    for part, pattern in PARTS.items():
        folder = root / part if part else root
        with contextlib.suppress(OSError), os.scandir(folder) as entries:
            for item in entries:
                if pattern.match(item.name):
                    with contextlib.suppress(OSError):
                        stat = item.stat(follow_symlinks=False)
                        if item.is_file(follow_symlinks=False):
                            found.append((part, item, stat))
    return found


def info(root: Path) -> FolderInfo:
    """Every part's files and bytes."""
    result = FolderInfo(root, {part: PartInfo() for part in PARTS})
    for part, _, stat in _scan(root):
        result.parts[part].files += 1
        result.parts[part].total_bytes += stat.st_size
    return result


def evict(root: Path, max_bytes: int) -> None:
    """Remove stale temporary files and claims, then the least recently used units until the whole
    store fits ``max_bytes``."""
    stale = time.time_ns() - int(GRACE_SECONDS * 1e9)
    units: dict[tuple[str, str], _Unit] = {}
    total = 0
    for part, item, stat in _scan(root):
        if _pending(item.name):
            if stat.st_mtime_ns < stale:
                with contextlib.suppress(OSError):
                    os.unlink(item.path)
                continue
            total += stat.st_size
            continue
        total += stat.st_size
        match = MODEL_FILE.match(item.name) if part == "" else None
        group = (part, match["key"] if match is not None else item.name)
        unit = units.setdefault(group, _Unit(0, 0, []))
        unit.size += stat.st_size
        unit.paths.append(Path(item.path))
        used = max(stat.st_mtime_ns, stat.st_atime_ns) if PARTS[part] is CONTENT_FILE else stat.st_mtime_ns
        unit.last_use_ns = max(unit.last_use_ns, used)
        if part == "" and item.name.endswith(".json"):  # a model's last use is its manifest's
            unit.used_ns = stat.st_mtime_ns
    in_use = time.time_ns() - int(IN_USE_SECONDS * 1e9)
    for (part, _), unit in sorted(units.items(), key=lambda item: item[1].last_use):
        if total <= max_bytes:
            break
        if PARTS[part] is CONTENT_FILE and _used_since(unit.paths, in_use):
            continue  # its times read again now: a use since the scan began counts
        for path in sorted(unit.paths, key=lambda path: path.suffix == ".json", reverse=True):
            with contextlib.suppress(OSError):  # a manifest first: its entry is gone before its files
                path.unlink()
        total -= unit.size


def _used_since(paths: list[Path], since_ns: int) -> bool:
    """Whether any of ``paths`` was used (accessed or modified) at or after ``since_ns``."""
    for path in paths:
        with contextlib.suppress(OSError):
            stat = path.stat()
            if max(stat.st_atime_ns, stat.st_mtime_ns) >= since_ns:
                return True
    return False


def clear(root: Path) -> FolderInfo:
    """Remove every file of every part, and the parts' folders left empty (nothing else); returns what
    was there and what could not go."""
    before = info(root)
    for _, item, _ in _scan(root):
        try:
            Path(item.path).unlink()
        except FileNotFoundError:
            continue  # another process removed it meanwhile
        except OSError as error:
            before.not_removed.append(f"{item.name}: {error.strerror}")
    for part in PARTS:
        if part:  # a part's own folder goes once empty (rmdir leaves one holding anything else)
            with contextlib.suppress(OSError):
                (root / part).rmdir()
    return before
