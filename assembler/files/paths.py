"""Where files are: the shipped specs and assets, and the files specs point at.

The shipped ``specs/`` and ``assets/`` folders sit at the top of a source checkout; a wheel
carries them inside the package as ``assembler/_shipped/``. Specs may also point into an
installed Python package with ``package://<package>/<path>`` (e.g. robosuite's own MJCF).

Specs may come from strangers, so the files they name are confined: after ``..`` and symbolic
links are resolved, a path must lie under the spec's own folder, the folders its spec repository
declares (:mod:`assembler.files.repositories`), the shipped folders, the package a ``package://``
reference names, or a folder the user allowed (``--allow-path DIR``, :func:`allow_paths`, or the
``ASSEMBLER_ALLOW_PATHS`` variable). Anything else is refused.
"""

from __future__ import annotations

import contextlib
import functools
import importlib.util
import os
from collections.abc import Iterable, Iterator
from pathlib import Path

from assembler.errors import AssemblerError, MissingPackageError, MjcfError, SpecError
from assembler.files import menagerie
from assembler.files.extras import install_hint
from assembler.files.inputs import note_resolution
from assembler.files.menagerie import MENAGERIE_SCHEME
from assembler.files.regular import not_regular
from assembler.files.repositories import MARKER, find_repository, git_top
from assembler.files.variables import restored_after

PACKAGE_SCHEME = "package://"

ALLOW_VARIABLE = "ASSEMBLER_ALLOW_PATHS"
"""Folders (separated by ``os.pathsep``) whose files any spec may read, besides its own folder."""

ALLOW_HINT = f"pass --allow-path DIR (or set {ALLOW_VARIABLE}) to allow it"

GIT_FOLDER = ".git"
"""A checkout's git folder (or file): never read for a spec, whatever folder would admit it (SECURITY.md)."""

_PACKAGE_DIR = Path(__file__).resolve().parent.parent  # assembler/, this file is in assembler/files/


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
    except (ValueError, OSError):  # elsewhere, or the working folder is gone
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


def allowed_folders() -> list[Path]:
    """The folders the user allowed beyond the defaults (from ``ASSEMBLER_ALLOW_PATHS``)."""
    value = os.environ.get(ALLOW_VARIABLE, "")
    return [_resolved_folder(Path(folder).expanduser()) for folder in value.split(os.pathsep) if folder]


@functools.lru_cache(maxsize=256)
def _resolved_folder(folder: Path) -> Path:
    # Root folders are resolved once per process: confine() checks every mesh of every part
    # against them, and resolving means one lstat per path component each time.
    return folder.resolve()


def allow_paths(*folders: str | Path) -> None:
    """Let specs read files below ``folders`` too, in this process and the processes it starts.

    The CLI's ``--allow-path DIR`` calls this. It extends ``ASSEMBLER_ALLOW_PATHS`` (so worker
    processes, e.g. of ``assembler variants``, inherit it); delete that variable to undo it.
    """
    current = [folder for folder in os.environ.get(ALLOW_VARIABLE, "").split(os.pathsep) if folder]
    added = [str(Path(folder).expanduser().resolve()) for folder in folders]
    os.environ[ALLOW_VARIABLE] = os.pathsep.join(dict.fromkeys([*current, *added]))


@contextlib.contextmanager
def allowing(folders: Iterable[str | Path]) -> Iterator[None]:
    """:func:`allow_paths` for the duration of a block (one CLI run), then as before."""
    with restored_after(ALLOW_VARIABLE):
        allow_paths(*folders)
        yield


def trusted_folders() -> list[Path]:
    """Folders every spec may read: the shipped specs and assets and the user's allowed folders."""
    return [_resolved_folder(shipped_specs_dir()), _resolved_folder(shipped_assets_dir()), *allowed_folders()]


_homes: dict[Path, set[Path]] = {}
"""For each file a spec named, the folders that admitted it (the spec's folder, a package's
root): the MJCF's meshes and textures may lie anywhere below them too."""


def homes_of(path: Path) -> set[Path]:
    """The folders that admitted ``path`` (resolved) when a spec named it."""
    return set(_homes.get(path, ()))


def confine(path: Path, homes: Iterable[Path], what: str, error: type[AssemblerError] = SpecError) -> Path:
    """``path`` resolved (``..`` and links followed), if it lies under ``homes`` or a trusted folder.

    Otherwise raises ``error`` with one line naming the path and how to allow it.
    """
    refuse_nul(str(path), what, error)
    try:
        resolved = path.resolve()
        roots = [*(_resolved_folder(home) for home in homes), *trusted_folders()]
    except (OSError, ValueError, RuntimeError) as problem:  # a loop of links, a NUL byte
        raise error(f"{what}{path}: cannot resolve this path ({problem})") from None
    admitting = [root for root in roots if resolved.is_relative_to(root)]
    written = Path(os.path.normpath(os.path.abspath(path)))
    link = f" (a link to {display_path(resolved)})" if resolved != written else ""
    if any(GIT_FOLDER in resolved.relative_to(root).parts for root in admitting):
        raise error(
            f"{what}{display_path(written)}{link} is inside a {GIT_FOLDER} folder, which a spec may never "
            "read (whatever a repository allows); name a file of the checkout itself"
        )
    if admitting:
        _homes.setdefault(resolved, set()).update(_resolved_folder(home) for home in homes)
        note_resolution(path, resolved)  # a link on the way: the cache checks it was not re-pointed
        return resolved
    reach, hint = _repository_advice(homes, resolved)
    raise error(
        f"{what}{display_path(written)}{link} is outside the folders a spec may read (its own "
        f"folder, {reach}the shipped specs and assets, installed packages); {ALLOW_HINT}{hint}"
    )


def _repository_advice(homes: Iterable[Path], refused: Path) -> tuple[str, str]:
    """What a refusal says about spec repositories: the reach of the one holding the spec, or how to
    declare one when the spec and the refused file share an undeclared git checkout."""
    homes = list(homes)
    reach = {_resolved_folder(home) for home in homes}
    undeclared = []
    for home in homes:
        try:
            repository = find_repository(home)
        except AssemblerError:  # a broken declaration was reported when the spec was read
            continue
        if repository is None:
            undeclared.append(home)
        elif set(repository.readable) <= reach:  # not a package's root that lies in a checkout
            inside = refused.is_relative_to(repository.root)
            hint = f", or name its folder in allow of {repository.where}" if inside else ""
            return "the folders its spec repository declares, ", hint
    for home in undeclared:
        top = git_top(home)
        if top is not None and refused.is_relative_to(top):
            return "", (
                f", or declare the checkout {top} a spec repository (an empty {MARKER} at its root "
                "lets its specs read its specs/ and assets/ folders; README: Spec repositories)"
            )
    return "", ""


def spec_homes(folder: Path) -> list[Path]:
    """The folders a spec in ``folder`` may read besides the trusted ones: ``folder`` itself and the
    folders its spec repository declares, if one holds it (:class:`SpecError` if that is invalid)."""
    shipped = (_resolved_folder(shipped_specs_dir()), _resolved_folder(shipped_assets_dir()))
    if any(folder.resolve().is_relative_to(root) for root in shipped):
        return [folder]  # a shipped spec reads the shipped folders; a repository around them is not its own
    repository = find_repository(folder)
    return [folder, *(repository.readable if repository is not None else ())]


def refuse_nul(text: str, what: str = "", error: type[AssemblerError] = SpecError) -> None:
    """A path written with a NUL character (YAML's ``\\0``) names no file: one line, no traceback."""
    if "\0" in text:
        prefix = f"{what.strip().rstrip(':')}: " if what.strip() else ""
        raise error(f"{prefix}a file path cannot contain a NUL character (\\0); remove it")


def resolve_model_path(reference: str, spec_dir: Path | None) -> str:
    """Turn a spec's file reference into an absolute path or keep a ``package://`` reference.

    Relative paths are taken relative to the spec's own folder (or the working directory for
    a spec given as a string), so a spec and its MJCF can move together. The path must stay below
    that folder, the folders of the spec repository holding it (:func:`spec_homes`) or a trusted
    one (:func:`confine`), whether or not it exists yet (a refusal says nothing about what exists
    outside); :class:`SpecError` otherwise. A ``package://NAME/...`` reference to a package the spec
    repository declares becomes that file's path; any other stays as written, for
    :func:`locate_model_file` (or the URDF importer) to find among the environment's packages.
    """
    refuse_nul(reference)
    home = spec_dir or Path.cwd()
    if reference.startswith(MENAGERIE_SCHEME):
        return reference  # found through the mujoco-menagerie library, at build time
    if reference.startswith(PACKAGE_SCHEME):
        declared = _declared_package_file(reference, home)
        return reference if declared is None else str(declared)
    path = Path(reference).expanduser()
    if not path.is_absolute():
        path = home / path
    return str(confine(path, spec_homes(home), ""))


def _declared_package_file(reference: str, home: Path) -> Path | None:
    """The file a ``package://`` reference names in a package the repository holding ``home``
    declares (confined to that package), or None when it declares no such package."""
    name, _, inner = reference[len(PACKAGE_SCHEME) :].partition("/")
    repository = find_repository(home)
    folder = repository.package(name) if repository is not None else None
    if folder is None:
        return None
    return confine(folder / inner, [folder], f"{reference}: ")


def is_file(path: str | Path) -> bool:
    """Whether ``path`` is a file; a name too long for the file system or holding a NUL is no file
    (``Path.is_file`` raises for those, and they come from users' specs and command lines)."""
    try:
        return Path(path).is_file()
    except (OSError, ValueError):
        return False


def is_dir(path: str | Path) -> bool:
    """Whether ``path`` is a folder, with :func:`is_file`'s tolerance of impossible names."""
    try:
        return Path(path).is_dir()
    except (OSError, ValueError):
        return False


def locate_model_file(reference: str) -> Path:
    """The file behind a resolved reference; raises :class:`MjcfError` saying what to do if absent.

    A ``package://`` path must stay inside its package's folder; every path is confined before its
    existence is looked at, so a refusal is the same for a missing file and an existing one.
    """
    refuse_nul(reference, error=MjcfError)
    if reference.startswith(PACKAGE_SCHEME):
        package, _, inner = reference[len(PACKAGE_SCHEME) :].partition("/")
        if not package.isidentifier():  # find_spec("a.b") would import package a
            raise MjcfError(f"{reference}: expected package://<top-level package>/<path in it>")
        root = package_root(package)
        if root is None:
            raise MissingPackageError(
                f"{reference}: Python package '{package}' is not installed; "
                f"install it{install_hint(package)}",
                package,
            )
        path = confine(root / inner, [root], f"{reference}: ", MjcfError)  # before existence: no oracle
    elif reference.startswith(MENAGERIE_SCHEME):
        inner_path, folder = menagerie.locate(reference)
        path = confine(inner_path, [folder], f"{reference}: ", MjcfError)
    else:
        path = Path(reference)  # admitted when its spec was loaded; checked again, it may be a link now
        path = confine(path, homes_of(path.resolve()), "", MjcfError)
    if not is_file(path):
        kind = not_regular(path)
        if kind is not None:  # a FIFO, a device or a folder is there: say what it is
            raise MjcfError(f"{display_path(path)}: {kind}")
        raise MjcfError(f"MJCF file not found: {display_path(path)}")
    return path
