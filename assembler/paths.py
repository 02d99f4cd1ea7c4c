"""Where files are: the shipped specs and assets, and the files specs point at.

The shipped ``specs/`` and ``assets/`` folders sit at the top of a source checkout; a wheel
carries them inside the package as ``assembler/_shipped/``. Specs may also point into an
installed Python package with ``package://<package>/<path>`` (e.g. robosuite's own MJCF).
"""

from __future__ import annotations

import importlib.util
from pathlib import Path

from assembler.errors import MissingPackageError, MjcfError

PACKAGE_SCHEME = "package://"

_PACKAGE_DIR = Path(__file__).resolve().parent


def _shipped(folder: str) -> Path:
    """The shipped folder, from a wheel's ``_shipped`` copy or a checkout's top level."""
    for candidate in (_PACKAGE_DIR / "_shipped" / folder, _PACKAGE_DIR.parent / folder):
        if candidate.is_dir():
            return candidate
    return _PACKAGE_DIR.parent / folder


def shipped_specs_dir() -> Path:
    """The folder of the YAML specs this project ships."""
    return _shipped("specs")


def shipped_assets_dir() -> Path:
    """The folder of the MJCF assets this project ships."""
    return _shipped("assets")


def display_path(path: str | Path) -> str:
    """A path as users like to read it: relative to the working directory when inside it."""
    resolved = Path(path)
    try:
        return str(resolved.relative_to(Path.cwd()))
    except ValueError:
        return str(resolved)


def package_root(package: str) -> Path | None:
    """The folder of an installed top-level Python package, without importing it."""
    try:
        found = importlib.util.find_spec(package)
    except (ImportError, ValueError):
        return None
    if found is None or not found.submodule_search_locations:
        return None
    return Path(next(iter(found.submodule_search_locations)))


def resolve_model_path(reference: str, spec_dir: Path | None) -> str:
    """Turn a spec's file reference into an absolute path or keep a ``package://`` reference.

    Relative paths are taken relative to the spec's own folder (or the working directory for
    a spec given as a string), so a spec and its MJCF can move together.
    """
    if reference.startswith(PACKAGE_SCHEME):
        return reference
    path = Path(reference).expanduser()
    if not path.is_absolute():
        path = (spec_dir or Path.cwd()) / path
    return str(path.resolve())


def locate_model_file(reference: str) -> Path:
    """The file behind a resolved reference; raises :class:`MjcfError` saying what to do if absent."""
    if reference.startswith(PACKAGE_SCHEME):
        package, _, inner = reference[len(PACKAGE_SCHEME) :].partition("/")
        root = package_root(package)
        if root is None:
            extra = ' (pip install "robot-assembler[robosuite]")' if package == "robosuite" else ""
            raise MissingPackageError(
                f"{reference}: Python package '{package}' is not installed; install it{extra}"
            )
        path = root / inner
    else:
        path = Path(reference)
    if not path.is_file():
        raise MjcfError(f"MJCF file not found: {display_path(path)}")
    return path
