"""What a robot, base or gripper argument names: a registered name, a spec file or a spec folder.

Every command and API that takes a part by name or by file asks :func:`argument_kind`, so a spec
file is recognised the same way everywhere (``assembler build``, ``load_model``, scenes, variants,
``list``): by its suffix, or by being a file; a folder's spec files are those with the suffix
(:func:`spec_files`). A path too long for the file system is no file (it
is then a name, and an unknown one gets the registry's own error). This module reads no spec and
imports nothing heavy: the cached fast path of ``load_model`` asks it too.
"""

from __future__ import annotations

import enum
from pathlib import Path

from assembler.files.paths import is_dir, is_file

SPEC_SUFFIXES = (".yaml", ".yml")
"""A spec file's suffixes."""


def spec_files(folder: Path) -> list[Path]:
    """Every spec file below ``folder``, in a stable order."""
    return sorted(p for p in folder.rglob("*") if p.suffix in SPEC_SUFFIXES and p.is_file())


DEFAULT = "default"
"""As a base or gripper argument: the robot spec's default base or gripper."""


class ArgumentKind(enum.Enum):
    """What a part argument names."""

    NAME = "name"
    SPEC_FILE = "spec file"
    SPEC_FOLDER = "spec folder"


def argument_kind(reference: str, folder: Path | None = None) -> ArgumentKind:
    """A spec file when ``reference`` ends in ``.yaml``/``.yml`` or is a file, a spec folder when it
    is a folder, otherwise a registered name; a relative path is taken from ``folder`` (a scene's or
    experiment's own folder), or from the working directory."""
    path = folder / reference if folder is not None else Path(reference)
    if reference.endswith(SPEC_SUFFIXES) or is_file(path):
        return ArgumentKind.SPEC_FILE
    if is_dir(path):
        return ArgumentKind.SPEC_FOLDER
    return ArgumentKind.NAME


def is_spec_file(reference: str, folder: Path | None = None) -> bool:
    """True when a part argument names a spec file rather than a registered part."""
    return argument_kind(reference, folder) is ArgumentKind.SPEC_FILE


def spec_file_path(reference: str) -> Path | None:
    """The absolute path of the spec file ``reference`` names, or None for a registered name."""
    return Path(reference).resolve() if is_spec_file(reference) else None
