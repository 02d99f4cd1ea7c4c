"""Spec repositories: a checkout whose specs may read its own spec and asset folders.

A lab keeps its robots as ``specs/`` beside ``assets/`` (the layout the README teaches), and a spec
names its MJCF as ``../assets/arm/arm.xml``: outside the spec's own folder, which is all a spec may
read by default (:mod:`assembler.files.paths`). A *spec repository* declares the folders its specs may
read, at its root, in one of (the first found wins, as ruff finds its configuration):

- ``robot-assembler.toml``, with the keys at the top level (an empty file means the defaults);
- ``pyproject.toml``, in a ``[tool.robot-assembler]`` table (a pyproject without it is not one).

Keys: ``specs`` (default ``["specs"]``), ``assets`` (default ``["assets"]``), ``allow`` (other
folders) and ``packages`` (ROS package folders, e.g. a vendor's ``z1_description`` beside its URDF:
what ``package://NAME`` in a URDF or a spec may name, besides the packages of the environment), each a
list of folders relative to the root. A package is named by its ``package.xml`` (``<name>``), or by
its folder without one. The declaration is found by walking up from
the spec's folder, symbolic links resolved first; the walk stops at the first folder holding
``.git`` (a repository's top: a declaration above it belongs to another project). Every folder it
names must lie inside the root once resolved (``..``, absolute paths and links leading out are
refused with one line), so a spec can only widen its reach to folders of the checkout holding it,
which the user chose to check out. SECURITY.md gives the reasoning.
"""

from __future__ import annotations

import functools
import importlib
import os
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from assembler.errors import SpecError, did_you_mean
from assembler.files.limits import MAX_SPEC_BYTES
from assembler.files.plain_xml import parse_plain_xml
from assembler.files.regular import FileTooLarge, read_bounded

TOML_MODULE = "tomllib" if sys.version_info >= (3, 11) else "tomli"
"""Imported on the first declaration read (~4 ms): a cached answer imports this module through
:mod:`assembler.files.paths` and reads no declaration."""

MARKER = "robot-assembler.toml"
"""A file at a repository's root that declares it a spec repository (for labs without a pyproject)."""

PYPROJECT = "pyproject.toml"
TABLE = "robot-assembler"
"""The ``[tool.robot-assembler]`` table of a pyproject.toml."""

DEFAULTS: dict[str, tuple[str, ...]] = {
    "specs": ("specs",),
    "assets": ("assets",),
    "allow": (),
    "packages": (),
}
"""The keys of a declaration and the folders each names when it is not given."""

EXAMPLES: dict[str, str] = {"allow": "meshes", "packages": "vendor/z1_description"}
"""A folder each key could name, for messages (the others name folders of their own name)."""


@dataclass(frozen=True)
class SpecRepository:
    """A declared spec repository: its root and the folders (resolved, inside it) its specs may read."""

    root: Path
    declared_in: Path
    """The ``robot-assembler.toml`` or ``pyproject.toml`` that declares it."""

    specs: tuple[Path, ...]
    assets: tuple[Path, ...]
    allowed: tuple[Path, ...]
    packages: tuple[tuple[str, Path], ...] = ()
    """The ROS packages it declares, as (name, folder resolved inside it)."""

    @property
    def readable(self) -> tuple[Path, ...]:
        """Every folder its specs may read, besides their own."""
        return (*self.specs, *self.assets, *self.allowed, *(folder for _, folder in self.packages))

    def package(self, name: str) -> Path | None:
        """The folder of the package ``name`` it declares, if it declares one."""
        return dict(self.packages).get(name)

    @property
    def where(self) -> str:
        """Where the declaration is written, e.g. ``pyproject.toml [tool.robot-assembler]``."""
        return _where(self.declared_in)


def _shown(path: Path) -> str:
    try:
        return str(path.relative_to(Path.cwd()))
    except (ValueError, OSError):  # elsewhere, or the working folder is gone
        return str(path)


def _where(declared_in: Path) -> str:
    return _shown(declared_in) + (f" [tool.{TABLE}]" if declared_in.name == PYPROJECT else "")


@functools.lru_cache(maxsize=64)
def _parsed(path: Path, mtime_ns: int, size: int) -> dict[str, Any]:
    """A TOML file's content, parsed once per version of the file (the walk passes every level)."""
    data = _bounded_bytes(path)
    toml = importlib.import_module(TOML_MODULE)
    try:
        parsed: dict[str, Any] = toml.loads(data.decode("utf-8"))
    except (toml.TOMLDecodeError, UnicodeDecodeError, RecursionError) as error:
        reason = "nested too deeply" if isinstance(error, RecursionError) else str(error)
        raise SpecError(f"{_shown(path)}: not valid TOML: {reason}") from None
    return parsed


def _bounded_bytes(path: Path) -> bytes:
    """A declaration's file (TOML, a package.xml), read with the spec-file size limit."""
    try:
        return read_bounded(path, MAX_SPEC_BYTES)
    except FileTooLarge:
        raise SpecError(f"{_shown(path)}: larger than the limit of {MAX_SPEC_BYTES} bytes") from None
    except OSError as error:
        raise SpecError(f"{_shown(path)}: cannot read it ({error.strerror or error})") from None


def _read(path: Path) -> dict[str, Any]:
    stat = path.stat()
    return _parsed(path, stat.st_mtime_ns, stat.st_size)


def _declaration(folder: Path) -> tuple[Path, dict[str, Any]] | None:
    """The declaration in ``folder`` (its file and settings), if it holds one."""
    marker = folder / MARKER
    if os.path.isfile(marker):
        return marker, _read(marker)
    pyproject = folder / PYPROJECT
    if os.path.isfile(pyproject):
        tool = _read(pyproject).get("tool")
        if isinstance(tool, dict) and TABLE in tool:
            table = tool[TABLE]
            if not isinstance(table, dict):
                raise SpecError(f"{_shown(pyproject)}: tool.{TABLE} must be a table ([tool.{TABLE}])")
            return pyproject, table
    return None


def _folders(root: Path, where: str, key: str, settings: dict[str, Any]) -> tuple[Path, ...]:
    """The folders ``key`` names, resolved; each must be a folder inside ``root``."""
    given = key in settings
    value = settings.get(key, DEFAULTS[key])
    if not isinstance(value, (list, tuple)) or not all(isinstance(item, str) for item in value):
        example = EXAMPLES.get(key, key)
        raise SpecError(f'{where}: {key} must be a list of folder names, e.g. {key} = ["{example}"]')
    folders = []
    for item in value:
        if "\0" in item or not item or os.path.isabs(item):
            raise SpecError(
                f"{where}: {key}: '{item}' is not a folder relative to the repository; "
                "name folders inside it, relative to its root"
            )
        folder = (root / item).resolve()  # links followed: a link leading out is refused below
        if not folder.is_relative_to(root):
            raise SpecError(
                f"{where}: {key}: '{item}' leads to {folder}, outside the repository {root}; "
                "a spec repository may only open its own folders to its specs"
            )
        if ".git" in folder.relative_to(root).parts:
            raise SpecError(
                f"{where}: {key}: '{item}' is inside the checkout's .git folder, which a spec may never "
                "read; name other folders"
            )
        if not folder.is_dir():
            if given:
                raise SpecError(f"{where}: {key}: '{item}' is not a folder of the repository {root}")
            continue  # a default folder the repository does not have
        folders.append(folder)
    return tuple(folders)


def package_name(folder: Path) -> str:
    """The name of the ROS package in ``folder``: its package.xml's ``<name>``, else the folder's name."""
    manifest = folder / "package.xml"
    if not os.path.isfile(manifest):
        return folder.name
    root = parse_plain_xml(_bounded_bytes(manifest), _shown(manifest), SpecError)
    return (root.findtext("name") or "").strip() or folder.name


def _packages(where: str, folders: tuple[Path, ...]) -> tuple[tuple[str, Path], ...]:
    """Each declared package folder by its name; two folders of one name are refused."""
    packages: dict[str, Path] = {}
    for folder in folders:
        name = package_name(folder)
        if name in packages:
            raise SpecError(
                f"{where}: packages: {packages[name]} and {folder} are both package '{name}'; "
                "declare one of them"
            )
        packages[name] = folder
    return tuple(packages.items())


def _repository(root: Path, declared_in: Path, settings: dict[str, Any]) -> SpecRepository:
    where = _where(declared_in)
    unknown = sorted(set(settings) - set(DEFAULTS))
    if unknown:
        key = unknown[0]
        raise SpecError(
            f"{where}: unknown key '{key}'.{did_you_mean(key, DEFAULTS)} Valid keys: {', '.join(DEFAULTS)}"
        )
    return SpecRepository(
        root=root,
        declared_in=declared_in,
        specs=_folders(root, where, "specs", settings),
        assets=_folders(root, where, "assets", settings),
        allowed=_folders(root, where, "allow", settings),
        packages=_packages(where, _folders(root, where, "packages", settings)),
    )


def git_top(folder: Path) -> Path | None:
    """The nearest folder at or above ``folder`` (resolved) holding ``.git``, if any."""
    start = folder.resolve()
    for candidate in (start, *start.parents):
        if os.path.lexists(candidate / ".git"):
            return candidate
    return None


def find_repository(folder: Path) -> SpecRepository | None:
    """The spec repository holding ``folder``, if one is declared at or above it (up to the
    first folder holding ``.git``); :class:`SpecError` when its declaration is invalid."""
    try:
        start = folder.resolve()
    except (OSError, RuntimeError, ValueError):
        return None
    for candidate in (start, *start.parents):
        declared = _declaration(candidate)
        if declared is not None:
            return _repository(candidate, *declared)
        if os.path.lexists(candidate / ".git"):
            return None  # the top of a checkout: what lies above is not this repository's
    return None
