"""MuJoCo Menagerie models by name, through the ``mujoco-menagerie`` library, never downloading.

A spec names a Menagerie file as ``menagerie://NAME@OID/FILE`` (``assembler new menagerie:NAME[/ENTRY]``
writes it): NAME is the library's robot name, OID the git tree id of the model folder the spec was
written from (its first 12 digits), FILE a path inside that folder. The folder is the library's own:
``$MENAGERIE_ROOT/NAME`` when that checkout is set, else the model's folder in the library's cache
(``$MENAGERIE_CACHE_DIR``), which the library's ``prefetch`` fills. Nothing here downloads: a model
not downloaded, a download whose files changed, an OID the installed library no longer serves and a
library not installed are each one line saying what to run. Every file is confined to its model's
folder, as a ``package://`` file is to its package.
"""

from __future__ import annotations

import importlib
import importlib.util
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from assembler.errors import MissingPackageError, MjcfError

MENAGERIE_SCHEME = "menagerie://"
NEW_PREFIX = "menagerie:"
"""How ``assembler new`` is given a Menagerie model: ``menagerie:NAME`` or ``menagerie:NAME/ENTRY``."""

OID_DIGITS = 12

LIBRARY = "mujoco_menagerie"


@dataclass(frozen=True)
class MenagerieModel:
    """One Menagerie model folder as the installed library serves it."""

    name: str
    oid: str
    license: str
    folder: Path
    library_version: str

    def reference(self, file: Path) -> str:
        """How a spec names ``file`` (inside :attr:`folder`)."""
        inside = file.resolve().relative_to(self.folder.resolve()).as_posix()
        return f"{MENAGERIE_SCHEME}{self.name}@{self.oid[:OID_DIGITS]}/{inside}"


def _library(what: str) -> Any:
    try:
        return importlib.import_module(LIBRARY)
    except ImportError:
        raise MissingPackageError(
            f"{what}: needs the mujoco-menagerie library: pip install mujoco-menagerie", "mujoco-menagerie"
        ) from None


def model(name: str, what: str, verify: bool = False) -> MenagerieModel:
    """The folder of Menagerie model ``name`` (``MENAGERIE_ROOT`` or the library's cache); one line
    when the library, the model or its download is missing (with ``verify``: or changed)."""
    library = _library(what)
    try:
        robot = library.get(name)
    except library.MenagerieError as error:
        raise MjcfError(f"{what}: {error}") from None
    cache = library.Cache()
    if cache.root is not None:
        folder = Path(cache.root) / robot.name
        if not folder.is_dir():
            raise MjcfError(f"{what}: {robot.name} is not in MENAGERIE_ROOT={cache.root}")
    elif cache.is_cached(robot):
        folder = Path(cache.model_path(robot))
        changed = cache.verify(robot) if verify else []
        if changed:
            raise MjcfError(
                f"{what}: {len(changed)} files of the downloaded {robot.name} changed since the download "
                f"(first {changed[0]}); run: python -m mujoco_menagerie clear, then prefetch {robot.name}"
            )
    else:
        raise MjcfError(
            f"{what}: {robot.name} is not downloaded; run: python -m mujoco_menagerie prefetch {robot.name} "
            "(or set MENAGERIE_ROOT to a Menagerie checkout)"
        )
    return MenagerieModel(robot.name, robot.oid, robot.license, folder, library.__version__)


def entry_file(argument: str) -> tuple[Path, MenagerieModel]:
    """``menagerie:NAME[/ENTRY]`` (``assembler new``'s argument): the entry's file (the robot's own
    model by default, not its scene) and its model, the download verified."""
    name, _, entry = argument[len(NEW_PREFIX) :].partition("/")
    found = model(name, argument, verify=True)
    robot = _library(argument).get(name)
    try:
        chosen = robot.entry(entry or robot.default_model)
    except Exception as error:  # the library's UnknownEntryPointError names the entries it has
        raise MjcfError(f"{argument}: {error}") from None
    return found.folder / chosen.file, found


def locate(reference: str) -> tuple[Path, Path]:
    """The file a ``menagerie://NAME@OID/FILE`` reference names and its model's folder; one line
    when the installed library serves another version of that model."""
    named, _, inner = reference[len(MENAGERIE_SCHEME) :].partition("/")
    name, _, oid = named.partition("@")
    if not name or not inner:
        raise MjcfError(
            f"{reference}: expected menagerie://NAME@OID/FILE (assembler new menagerie:NAME writes it)"
        )
    found = model(name, reference)
    if oid and not found.oid.startswith(oid):
        raise MjcfError(
            f"{reference}: written for {name} at {oid}; mujoco-menagerie {found.library_version} serves "
            f"{found.oid[:OID_DIGITS]}: install the version that serves it, or run assembler new "
            f"{NEW_PREFIX}{name} again and review the change"
        )
    return found.folder / inner, found.folder


def oid_now(name: str) -> str | None:
    """The OID the installed library serves for ``name`` (no download, no folder needed)."""
    try:
        library = importlib.import_module(LIBRARY)
        return str(library.get(name).oid)
    except Exception:  # not installed, or no such robot any more
        return None


def reference_of(path: Path) -> str | None:
    """How a spec names ``path`` when it lies in a Menagerie model folder (under ``MENAGERIE_ROOT`` or
    the library's cache), else None; nothing is imported unless the library is installed."""
    if importlib.util.find_spec(LIBRARY) is None:
        return None
    library = importlib.import_module(LIBRARY)
    cache = library.Cache()
    resolved = path.resolve()
    for base, strip_oid in ((cache.root, False), (Path(cache.dir) / "models", True)):
        if base is None or not resolved.is_relative_to(Path(base).resolve()):
            continue
        folder = resolved.relative_to(Path(base).resolve()).parts[0]
        name = folder.rsplit("-", 1)[0] if strip_oid else folder
        try:
            return model(name, str(path)).reference(resolved)
        except MjcfError:
            return None
    return None
