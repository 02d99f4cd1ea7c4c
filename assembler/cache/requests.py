"""Request records: a request made before (a robot by name or spec file, with its idn, base,
grippers and overrides, exactly as given) answered from the cache without reading any spec.

The compile service's key (:mod:`assembler.cache.key`) is a hash of the validated specs, so
finding it means importing the schema and reading every shipped spec: about 0.3 s, more than
MuJoCo takes to load a cached Panda. A request record maps the request itself to that key. Its
own key covers the request as given, the assembler's code, MuJoCo's version, the Python
environment (``sys.prefix`` and the import path, which decide what ``package://`` means), the
working folder (relative names), the allowed folders and the cache format. The record lists every
spec file that went into the answer (the robot's, its parents', its base's and grippers'), by
size, time and digest like a model's dependencies, and the time of every spec folder the registry
was read from (a spec file added or removed there is a miss, as it may clash with a name). Any
difference is a miss, and the slow path answers and records again: a record never answers for
anything the slow path would answer differently.

Records are small JSON files in ``requests/`` beside the model entries, written atomically,
touched on use and bounded in number (least recently used go first); an unreadable one is removed.
"""

from __future__ import annotations

import contextlib
import hashlib
import json
import os
import sys
import tempfile
import time
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import asdict, dataclass, replace
from pathlib import Path
from typing import Any

import mujoco

from assembler.cache.dependencies import Dependency, verify
from assembler.cache.key import code_fingerprint, resolution_environment
from assembler.files.cache_location import cache_dir
from assembler.files.inputs import note_inputs
from assembler.files.regular import read_regular

FORMAT = 1
"""Version of the record layout and of the request key's contents."""

FOLDER = "requests"
"""Where records live, below the cache folder."""

MAX_RECORDS = 2048
"""Records kept at most (each a few hundred bytes); the least recently used go first."""

ALLOW_VARIABLE = "ASSEMBLER_ALLOW_PATHS"
"""Folders every spec may read (:mod:`assembler.files.paths`; named here so this module stays light)."""


@dataclass(frozen=True)
class Folder:
    """A spec folder the registry read, by its modification time (changed by adding, removing or
    renaming a file in it)."""

    path: str
    mtime_ns: int


@dataclass(frozen=True)
class RequestRecord:
    """What a request was answered with, and what the answer was made from."""

    model_key: str
    """The compile service's key of the answer (the model entry)."""

    specs: tuple[Dependency, ...]
    """Every spec file the answer was made from."""

    folders: tuple[Folder, ...]
    """Every folder the registry read specs from."""

    notes: tuple[str, ...] = ()
    """Lines the slow path printed besides the answer (``build``'s warnings), printed again."""

    name: str = ""
    """The robot's class name (``build --bundle`` names its XML after it)."""

    def to_json(self) -> str:
        """The record's text."""
        return json.dumps({"format": FORMAT, **asdict(self)}, indent=1)

    @classmethod
    def from_json(cls, text: str) -> RequestRecord:
        """Parse a record; ValueError for anything that is not a whole record of this format."""
        try:
            data = json.loads(text)
            if data.pop("format") != FORMAT:
                raise ValueError("another format")
            return cls(
                model_key=str(data["model_key"]),
                specs=tuple(Dependency(**d) for d in data["specs"]),
                folders=tuple(Folder(**f) for f in data["folders"]),
                notes=tuple(str(note) for note in data["notes"]),
                name=str(data["name"]),
            )
        except (KeyError, TypeError, AttributeError) as error:
            raise ValueError(f"not a request record: {error}") from None


def request_key(request: Mapping[str, Any]) -> str | None:
    """The key of ``request`` (plain JSON data) in this environment, or None when the request
    holds something that is not plain data (it cannot be compared across processes) or the working
    folder is gone (deleted under the process: what relative paths meant then is unknown)."""
    try:
        cwd = os.getcwd()
        path = [os.path.abspath(entry) for entry in sys.path]
    except OSError:
        return None
    material = {
        "format": FORMAT,
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "environment": resolution_environment(),
        "path": path,
        "cwd": cwd,
        "allowed": os.environ.get(ALLOW_VARIABLE, ""),
        "request": request,
    }
    try:
        text = json.dumps(material, sort_keys=True, separators=(",", ":"), allow_nan=False)
    except (TypeError, ValueError, RecursionError):  # a value nested too deep is refused later, in a line
        return None
    return hashlib.blake2b(text.encode(), digest_size=20).hexdigest()


def folder_stats(roots: Iterable[Path]) -> tuple[Folder, ...]:
    """Every folder below ``roots`` (themselves included), by modification time."""
    found: dict[str, int] = {}
    for root in roots:
        for folder, _, _ in os.walk(root, followlinks=True):
            with contextlib.suppress(OSError):
                found[folder] = os.stat(folder).st_mtime_ns
    return tuple(Folder(path, mtime) for path, mtime in sorted(found.items()))


def _folders_unchanged(folders: Sequence[Folder]) -> bool:
    try:
        return all(os.stat(folder.path).st_mtime_ns == folder.mtime_ns for folder in folders)
    except OSError:
        return False


class RequestStore:
    """Request records in ``directory``, at most ``max_records`` of them."""

    def __init__(self, directory: Path, max_records: int = MAX_RECORDS) -> None:
        self.directory = directory
        self.max_records = max_records

    def _path(self, key: str) -> Path:
        return self.directory / f"{key}.json"

    def load(self, key: str) -> RequestRecord | None:
        """The record of ``key``, if every spec file and folder it lists is unchanged."""
        path = self._path(key)
        try:
            record = RequestRecord.from_json(read_regular(path).decode("utf-8"))
        except (OSError, UnicodeDecodeError):
            return None
        except ValueError:
            path.unlink(missing_ok=True)
            return None
        if not _folders_unchanged(record.folders):
            return None
        current = verify(record.specs)
        if current is None:
            return None
        note_inputs(state.path for state in current)
        with contextlib.suppress(OSError):
            if any(new is not old for new, old in zip(current, record.specs, strict=True)):
                self.save(key, replace(record, specs=tuple(current)))
            else:
                now = time.time_ns()
                os.utime(path, ns=(now, now))
        return record

    def save(self, key: str, record: RequestRecord) -> None:
        """Write ``record`` atomically (a failure only means no record), then keep the newest."""
        try:
            self.directory.mkdir(parents=True, exist_ok=True)
            handle, temporary = tempfile.mkstemp(prefix=f".{key}.", suffix=".tmp", dir=self.directory)
            try:
                with os.fdopen(handle, "w", encoding="utf-8") as stream:
                    stream.write(record.to_json())
                os.replace(temporary, self._path(key))
            finally:
                Path(temporary).unlink(missing_ok=True)
        except OSError:
            return
        self.evict()

    def evict(self) -> None:
        """Remove the least recently used records beyond the bound, and temporary files left by
        writers that died (older than a minute).

        The whole cache folder's bound is not enforced here: that scans every file of every part
        (about 60 ms for a cache of 4,000 files, paid by every first request), and records, a few
        hundred bytes each and at most :data:`MAX_RECORDS`, cannot be what takes the folder over
        it. The writers of models and meshes enforce it, and count the records."""
        records: list[tuple[int, Path]] = []
        now = time.time_ns()
        try:
            with os.scandir(self.directory) as entries:
                for item in entries:
                    with contextlib.suppress(OSError):
                        stamp = item.stat().st_mtime_ns
                        if item.name.endswith(".json"):
                            records.append((stamp, Path(item.path)))
                        elif item.name.endswith(".tmp") and now - stamp > 60_000_000_000:
                            os.unlink(item.path)
        except OSError:
            return
        for _, path in sorted(records)[: max(0, len(records) - self.max_records)]:
            path.unlink(missing_ok=True)


def default_request_store() -> RequestStore:
    """The records of the cache the environment points at."""
    return RequestStore(cache_dir() / FOLDER)
