"""Where a ROS package's files are: ``package://NAME/path`` in URDF mesh URIs and in a spec's ``urdf:``.

ROS resolves ``package://NAME/...`` through its package index; without ROS we look where ROS-style
packages are installed, in this order (the first folder that holds the file wins):

1. the packages the spec repository holding the URDF declares (``packages = ["vendor/z1_description"]``
   in its ``robot-assembler.toml`` or ``[tool.robot-assembler]``; :mod:`assembler.files.repositories`);
2. ``ROS_PACKAGE_PATH``: each entry that is the package itself or holds it as a sub-folder;
3. ``AMENT_PREFIX_PATH``: ``<prefix>/share/NAME`` of each prefix (ROS 2);
4. the Python environment's prefixes: ``<sys.prefix>/share/NAME`` (conda, robostack) and
   ``<site-packages>/cmeel.prefix/share/NAME`` (cmeel wheels such as ``example-robot-data``).

Only these are package roots. A folder is never taken for package ``NAME`` because it is called
``NAME`` or holds a ``package.xml`` saying so: a stranger's URDF in a checkout named ``lab`` could
otherwise name ``package://lab/private/token.obj`` and read the whole checkout.

The folder found is the package's home: its files may be read, nothing outside it
(:func:`assembler.files.paths.confine`, checked before the file's existence is looked at, so a
refusal says nothing about what exists outside).
"""

from __future__ import annotations

import os
import re
import sys
import sysconfig
from collections.abc import Iterator
from pathlib import Path

from assembler.cache.key import PACKAGE_VARIABLES
from assembler.errors import MjcfError
from assembler.files.extras import install_command
from assembler.files.paths import confine, display_path, is_file
from assembler.files.regular import not_regular
from assembler.files.repositories import MARKER, find_repository

PACKAGE_SCHEME = "package://"

ROS_PACKAGE_NAME = re.compile(r"^[A-Za-z0-9][A-Za-z0-9_.\-]*$")
"""A ROS package name as it may appear in a URI (no path separators, not '.' or '..')."""

INSTALL_EXTRAS: dict[str, str] = {"example-robot-data": "urdf"}
"""The extra of this project that installs a ROS package a shipped spec reads."""


def split_package_uri(uri: str) -> tuple[str, str] | None:
    """``("NAME", "inner/path")`` of ``package://NAME/inner/path``; None for other text or a bad name."""
    if not uri.startswith(PACKAGE_SCHEME):
        return None
    name, _, inner = uri[len(PACKAGE_SCHEME) :].partition("/")
    if not ROS_PACKAGE_NAME.match(name) or ".." in name:
        return None
    return name, inner


def declared_package(urdf: Path, name: str) -> Path | None:
    """The folder of package ``name`` if the spec repository holding ``urdf`` declares it."""
    repository = find_repository(urdf.parent)
    return repository.package(name) if repository is not None else None


def _environment_prefixes() -> Iterator[Path]:
    yield Path(sys.prefix)
    for key in ("purelib", "platlib"):
        yield Path(sysconfig.get_paths()[key]) / "cmeel.prefix"


def _entries(variable: str) -> list[Path]:
    return [Path(entry) for entry in os.environ.get(variable, "").split(os.pathsep) if entry]


def package_folders(name: str, urdf: Path | None = None) -> list[Path]:
    """Every existing folder of package ``name``, in the order documented above (no duplicates)."""
    candidates: list[Path] = []
    if urdf is not None and (declared := declared_package(urdf, name)) is not None:
        candidates.append(declared)
    for entry in _entries("ROS_PACKAGE_PATH"):
        candidates += [entry] if entry.name == name else [entry / name]
    candidates += [prefix / "share" / name for prefix in _entries("AMENT_PREFIX_PATH")]
    candidates += [prefix / "share" / name for prefix in _environment_prefixes()]
    found: list[Path] = []
    for folder in candidates:
        if folder.is_dir() and folder.resolve() not in found:
            found.append(folder.resolve())
    return found


def share_reference(path: Path) -> str | None:
    """``package://NAME/inner/path`` when ``path`` lies in a ``share/NAME`` folder of this Python
    environment or of ``AMENT_PREFIX_PATH`` (cmeel's ``.../cmeel.prefix/share/example-robot-data/...``)
    and that folder is the first package ``NAME`` resolves to, as a spec's ``package://`` reads it;
    else None. Such a reference reads the same file on every machine the package is installed on."""
    resolved = path.resolve()
    prefixes = [*_entries("AMENT_PREFIX_PATH"), *_environment_prefixes()]
    for share in dict.fromkeys(prefix.resolve() / "share" for prefix in prefixes if prefix.is_dir()):
        if not resolved.is_relative_to(share) or resolved.parent == share:
            continue
        name, *inner = resolved.relative_to(share).parts
        folders = package_folders(name) if ROS_PACKAGE_NAME.match(name) else []
        if inner and folders and folders[0] == share / name:
            return f"{PACKAGE_SCHEME}{name}/{'/'.join(inner)}"
    return None


def resolution_state(urdf: Path) -> tuple[object, ...]:
    """Everything :func:`package_folders` reads besides the files: the package variables, the Python
    environment and the packages the spec repository holding ``urdf`` declares. A URDF read with
    other values is read again (a notebook that points ``ROS_PACKAGE_PATH`` at another copy)."""
    repository = find_repository(urdf.parent)
    declared = repository.packages if repository is not None else ()
    return (*(os.environ.get(name, "") for name in PACKAGE_VARIABLES), sys.prefix, declared)


def find_package_file(uri: str, urdf: Path | None = None, what: str = "") -> tuple[Path, Path] | None:
    """``(file, package folder)`` for a ``package://`` URI, or None when no package folder holds it.

    A path that leaves its package (``..``, a link) is refused (:class:`MjcfError`, ``what`` before
    the path) whether or not the file it names exists."""
    parts = split_package_uri(uri)
    if parts is None:
        return None
    name, inner = parts
    for folder in package_folders(name, urdf):
        candidate = confine(folder / inner, [folder], what, MjcfError)
        if is_file(candidate):
            return candidate, folder
    return None


def not_found_message(uri: str, urdf: Path | None = None) -> str:
    """Why ``uri`` could not be resolved and what to do, as one line."""
    parts = split_package_uri(uri)
    if parts is None:
        return f"{uri}: expected package://<package>/<path in it>"
    name, inner = parts
    folders = package_folders(name, urdf)
    for folder in folders:  # something is there that is no file (a FIFO, a folder): say what
        kind = not_regular(folder / inner)
        if kind is not None:
            return f"{uri}: {display_path(folder / inner)}: {kind}"
    if folders:
        return f"{uri}: no file '{inner}' in package '{name}' (looked in {', '.join(map(str, folders))})"
    extra = INSTALL_EXTRAS.get(name)
    todo = (
        f"install it: {install_command(extra)}"
        if extra
        else _declare_hint(name, urdf) + "or set ROS_PACKAGE_PATH or AMENT_PREFIX_PATH to where it is"
    )
    where = "the packages its spec repository declares, " if urdf is not None else ""
    return (
        f"{uri}: package '{name}' not found (searched {where}ROS_PACKAGE_PATH, AMENT_PREFIX_PATH and "
        f"the share/ folders of this Python environment); {todo}"
    )


def _declare_hint(name: str, urdf: Path | None) -> str:
    """How to declare the package: the exact line when a folder above the URDF looks like package
    ``name`` (named so, with a package.xml), as a vendor's package beside its URDF does."""
    general = (
        f"declare its folder in packages of the spec repository's {MARKER} (README: Spec repositories), "
    )
    if urdf is None:
        return general
    looks = next((f for f in urdf.parents if f.name == name and os.path.isfile(f / "package.xml")), None)
    if looks is None:
        return general
    repository = find_repository(urdf.parent)
    if repository is None or not looks.is_relative_to(repository.root):
        return (
            f"if {display_path(looks)} is that package, declare it in packages of a {MARKER} at the top of "
            "your checkout, "
        )
    line = f'packages = ["{looks.relative_to(repository.root).as_posix()}"]'
    return f"if {display_path(looks)} is that package, declare it: {line} in {repository.where}, "
