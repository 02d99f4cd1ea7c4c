"""MJCF text written for robosuite, which reads models from files: content-addressed files in the
cache folder (atomic, so a killed run never leaves a half file for the next one), remembered per
process so an environment's every reset does not write again."""

from __future__ import annotations

import hashlib
import tempfile
from pathlib import Path

from assembler.cache.settings import cache_dir
from assembler.files.writing import write_atomically

FOLDER = "robosuite"
"""Below the cache folder."""

_written: dict[str, Path] = {}


def written_file(text: str) -> str:
    """The path of a file holding ``text`` (written once per content)."""
    digest = hashlib.sha256(text.encode()).hexdigest()
    path = _written.get(digest)
    if path is not None and path.is_file():
        return str(path)
    folder = _folder()
    path = folder / f"{digest[:32]}.xml"
    if not path.is_file():
        write_atomically(path, text)
    _written[digest] = path
    return str(path)


def _folder() -> Path:
    """The cache's ``robosuite/`` folder, or a temporary one when the cache folder cannot be written."""
    folder = cache_dir() / FOLDER
    try:
        folder.mkdir(parents=True, exist_ok=True)
        probe = tempfile.NamedTemporaryFile(dir=folder, delete=True)  # noqa: SIM115 - a check, closed at once
        probe.close()
        return folder
    except OSError:
        fallback = Path(tempfile.gettempdir()) / f"robot-assembler-{FOLDER}"
        fallback.mkdir(parents=True, exist_ok=True)
        return fallback
