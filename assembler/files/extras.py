"""What to install for a ``package://`` package a spec reads: an extra's requirements, as pip takes them.

robot-assembler is installed from a clone or a wheel, not from an index, so
``pip install "robot-assembler[robosuite]"`` fails on a fresh machine. The extra's own requirements
(read from the installed distribution's metadata, so they never drift from pyproject.toml) work
wherever pip does.
"""

from __future__ import annotations

import importlib
import re
from types import ModuleType

DISTRIBUTION = "robot-assembler"

EXTRAS: dict[str, str] = {"robosuite": "robosuite"}
"""Top-level package -> the extra of this project that installs it."""


def _metadata() -> ModuleType:
    # importlib.metadata pulls in email, csv, socket and calendar (~15 ms): every cached answer
    # imports this module through assembler.files.paths, and only an error message reads metadata.
    return importlib.import_module("importlib.metadata")


def extra_requirements(extra: str) -> list[str]:
    """The requirements of one of our extras (e.g. ``robosuite==1.5.2``), from the installed metadata."""
    metadata = _metadata()
    try:
        requirements = metadata.requires(DISTRIBUTION) or []
    except metadata.PackageNotFoundError:  # run from a source tree that is not installed
        return []
    marker = re.compile(rf"""extra\s*==\s*["']{re.escape(extra)}["']""")
    return [line.split(";")[0].strip() for line in requirements if marker.search(line)]


def install_command(extra: str) -> str:
    """How to install one of our extras, e.g. ``pip install robosuite==1.5.2 (the robosuite extra; in a
    clone: pip install ".[robosuite]")``."""
    requirements = sorted(extra_requirements(extra), key=lambda r: not r.startswith(extra)) or [extra]
    clone = f'pip install ".[{extra}]"'
    return f"pip install {' '.join(requirements)} (the {extra} extra; in a clone: {clone})"


def install_hint(package: str) -> str:
    """How to install a missing package, e.g. `` with pip install robosuite==1.5.2 ...``; empty for a
    package no extra installs."""
    extra = EXTRAS.get(package)
    return "" if extra is None else f" with {install_command(extra)}"
