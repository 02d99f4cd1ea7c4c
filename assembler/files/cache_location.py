"""Where the compiled-model cache lives, how large it may grow, and whether it is on.

Everything is read from the environment at each use (not at import), so a test or a script can
point the cache elsewhere or switch it off by setting a variable:

- ``ASSEMBLER_CACHE_DIR``: the folder (default ``$XDG_CACHE_HOME/robot-assembler``, else
  ``~/.cache/robot-assembler``);
- ``ASSEMBLER_CACHE_MAX_BYTES``: the size bound, e.g. ``2G``, ``500M`` or a number of bytes;
- ``ASSEMBLER_NO_CACHE``: any value but empty, ``0`` or ``false`` turns the cache off.
"""

from __future__ import annotations

import atexit
import contextlib
import os
import re
import shutil
import tempfile
from collections.abc import Iterator
from pathlib import Path

from assembler.errors import AssemblerError
from assembler.files.variables import restored_after

DIR_VARIABLE = "ASSEMBLER_CACHE_DIR"
MAX_BYTES_VARIABLE = "ASSEMBLER_CACHE_MAX_BYTES"
DISABLE_VARIABLE = "ASSEMBLER_NO_CACHE"

DEFAULT_MAX_BYTES = 2 * 1024**3
"""2 GiB: about forty robosuite robots with meshes (a Panda with its gripper is 44 MB compiled)."""

_UNITS = {"": 1, "K": 1024, "M": 1024**2, "G": 1024**3, "T": 1024**4}
_SIZE = re.compile(r"^\s*(\d+(?:\.\d+)?)\s*([KMGT]?)(?:I?B)?\s*$", re.IGNORECASE)


def cache_dir() -> Path:
    """The cache folder (it may not exist yet)."""
    explicit = os.environ.get(DIR_VARIABLE)
    if explicit:
        return Path(explicit).expanduser()
    xdg = os.environ.get("XDG_CACHE_HOME")
    root = Path(xdg).expanduser() if xdg else Path.home() / ".cache"
    return root / "robot-assembler"


_scratch: list[Path] = []


def scratch_dir() -> Path:
    """A folder of this process's own, removed at its exit: where files the cache would keep (a
    converted mesh, a robosuite part file) go when the cache is off or cannot be written."""
    if not _scratch:
        folder = Path(tempfile.mkdtemp(prefix="robot-assembler-"))
        atexit.register(shutil.rmtree, folder, True)
        _scratch.append(folder)
    return _scratch[0]


def volatile_folders() -> list[Path]:
    """Folders whose files may vanish (the cache folder, the scratch folder): a written model never
    names a file in them."""
    return [cache_dir(), *_scratch]


def cache_disabled() -> bool:
    """True when ``ASSEMBLER_NO_CACHE`` asks for no cache."""
    value = os.environ.get(DISABLE_VARIABLE, "").strip().lower()
    return value not in ("", "0", "false", "no")


@contextlib.contextmanager
def switched_off(off: bool) -> Iterator[None]:
    """With ``off``, the cache is off inside the block for every layer and every worker process
    (``--no-cache``: nothing is read from the cache folder, also converted meshes and part files)."""
    if not off:
        yield
        return
    with restored_after(DISABLE_VARIABLE):
        os.environ[DISABLE_VARIABLE] = "1"
        yield


def parse_size(text: str) -> int:
    """Bytes from ``"2G"``, ``"500M"``, ``"1.5GiB"`` or ``"1048576"`` (powers of 1024)."""
    match = _SIZE.match(text)
    if match is None:
        raise AssemblerError(
            f"{MAX_BYTES_VARIABLE}: expected a size such as 2G, 500M or 1048576, got '{text}'"
        )
    return int(float(match.group(1)) * _UNITS[match.group(2).upper()])


def max_bytes() -> int:
    """The size bound: ``ASSEMBLER_CACHE_MAX_BYTES`` or 2 GiB."""
    value = os.environ.get(MAX_BYTES_VARIABLE, "").strip()
    return parse_size(value) if value else DEFAULT_MAX_BYTES


def format_size(size: int) -> str:
    """A byte count for people: ``44.1 MB``, ``2.0 GB`` (powers of 1024, as the limit is parsed)."""
    amount, unit = float(size), "B"
    for larger in ("KB", "MB", "GB"):
        if amount < 1024:
            break
        amount, unit = amount / 1024, larger
    return f"{size} B" if unit == "B" else f"{amount:.1f} {unit}"
