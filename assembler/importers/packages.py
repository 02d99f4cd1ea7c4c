"""ROS packages a URDF names that nothing resolves, found beside it, for ``assembler new``.

pybullet's xArm6 names its meshes ``package://xarm_description/...``, and ``xarm_description/`` lies
in the URDF's own folder; ``package://`` resolves only to real package roots (:mod:`assembler.urdf.
packages`), so nothing finds it until the user says where it is. ``new`` looks for a folder of that
name holding the files named, in the URDF's folder and the two above it, reads the URDF with it, and
says exactly what to add, in the first place that works:

1. the spec repository holding the URDF: the ``packages = [...]`` entry for its declaration;
2. the folder the spec is written to, when the URDF lies below it and no repository holds the URDF:
   ``new`` writes ``robot-assembler.toml`` there with that entry (beside the spec, never elsewhere,
   never in the vendor's files);
3. otherwise (the URDF is in an installed Python package, or outside the spec's folder): the
   environment, ``ROS_PACKAGE_PATH`` holding the folder, since a repository may only name folders
   inside it, and a spec names an installed package's URDF as ``package://`` whatever machine it is
   on (a declaration would name this machine's install, e.g. a venv inside the checkout).
"""

from __future__ import annotations

import contextlib
import json
import os
import re
from collections.abc import Iterator, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from assembler.files.limits import MAX_MJCF_BYTES
from assembler.files.paths import display_path
from assembler.files.regular import open_regular
from assembler.files.repositories import MARKER, find_repository
from assembler.files.variables import restored_after
from assembler.importers.reading import python_package_reference
from assembler.urdf.packages import package_folders, share_reference, split_package_uri

PACKAGE_URI = re.compile(r"""package://[^"'\s<>]+""")
"""A ``package://`` URI as a URDF writes it in an attribute."""

LEVELS = 3
"""The URDF's folder and the two above it: where a vendor keeps the package beside its URDF (ROS's
``NAME/urdf/robot.urdf`` beside ``NAME/meshes``)."""

VARIABLE = "ROS_PACKAGE_PATH"


@dataclass(frozen=True)
class BesidePackage:
    """A package the URDF names, the folder beside it that holds the files, and what the user adds."""

    name: str
    folder: Path
    todo: str
    """One sentence: what to add where (or what ``new`` wrote)."""
    declared: Literal["repository", "beside the spec", "environment"]
    """Where it is declared: the URDF's spec repository (the user adds the entry), a
    ``robot-assembler.toml`` ``new`` writes beside the spec, or ``ROS_PACKAGE_PATH``."""
    entry: str = ""
    """The folder as a declaration names it, relative to the repository's root."""


def _named(urdf: Path) -> dict[str, list[str]]:
    """Package name -> the paths inside it that the URDF names."""
    with open_regular(urdf) as stream:  # bounded: the reader refuses a larger file with its own line
        text = stream.read(MAX_MJCF_BYTES).decode("utf-8", errors="replace")
    named: dict[str, list[str]] = {}
    for uri in PACKAGE_URI.findall(text):
        parts = split_package_uri(uri)
        if parts is not None:
            named.setdefault(parts[0], []).append(parts[1])
    return named


def _beside(urdf: Path, name: str, inner: list[str]) -> Path | None:
    for level in [urdf.parent, *urdf.parent.parents][:LEVELS]:
        for folder in ([level] if level.name == name else []) + [level / name]:
            if folder.is_dir() and any((folder / path).is_file() for path in inner):
                return folder.resolve()
    return None


def _reaches(urdf: Path, spec_dir: Path) -> bool:
    """Whether a declaration in ``spec_dir`` is the one found from the URDF's folder: the URDF lies
    below it and no folder in between holds ``.git`` (the walk up stops there)."""
    start, top = urdf.parent.resolve(), spec_dir.resolve()
    if not start.is_relative_to(top):
        return False
    return not any(
        os.path.lexists(f / ".git") for f in (start, *start.parents) if f != top and f.is_relative_to(top)
    )


def _package(urdf: Path, name: str, folder: Path, spec_dir: Path) -> BesidePackage:
    shown = f"package://{name} is the folder {display_path(folder)} beside the URDF"
    # A URDF of an installed Python package is named package://..., the same on every machine: a
    # declaration would name this machine's install (a venv inside the checkout: .venv/lib/python3.11/...)
    if python_package_reference(urdf) is None and share_reference(urdf) is None:
        repository = find_repository(urdf.parent)
        if repository is not None and folder.is_relative_to(repository.root):
            entry = folder.relative_to(repository.root).as_posix()
            todo = f'{shown}: add "{entry}" to packages in {repository.where}'
            return BesidePackage(name, folder, todo, "repository", entry)
        if repository is None and folder.is_relative_to(spec_dir.resolve()) and _reaches(urdf, spec_dir):
            entry = folder.relative_to(spec_dir.resolve()).as_posix()
            todo = f"{shown}: declared in {display_path(spec_dir / MARKER)}, which new wrote"
            return BesidePackage(name, folder, todo, "beside the spec", entry)
    todo = f"{shown}: set {VARIABLE} to hold it (a spec repository may name only folders inside it)"
    return BesidePackage(name, folder, todo, "environment")


def packages_beside(urdf: Path, spec_dir: Path) -> list[BesidePackage]:
    """The packages the URDF names that no package root holds (with the files named: pybullet's Panda
    names ``package://meshes``, which xArm's package folder on ROS_PACKAGE_PATH also holds), each found
    beside the URDF."""
    found = []
    for name, inner in _named(urdf).items():
        roots = package_folders(name, urdf)
        if any((folder / path).is_file() for folder in roots for path in inner):
            continue  # a package root holds it (one holding none of its files is another package)
        folder = _beside(urdf, name, inner)
        if folder is not None:
            found.append(_package(urdf, name, folder, spec_dir))
    return found


def declaration(packages: Sequence[BesidePackage]) -> str | None:
    """The ``robot-assembler.toml`` ``new`` writes beside the spec, if it declares any package."""
    beside = [package for package in packages if package.declared == "beside the spec"]
    if not beside:
        return None
    entries = [package.entry for package in beside]
    names = ", ".join(f"package://{package.name}" for package in beside)
    return (
        f"# Written by `assembler new`: the URDF beside this file names {names}, found in the folders below\n"
        "# (README: Spec repositories). This file makes this folder a spec repository.\n"
        f"packages = [{', '.join(json.dumps(entry) for entry in entries)}]\n"
    )


def environment(packages: Sequence[BesidePackage]) -> dict[str, str]:
    """``ROS_PACKAGE_PATH`` as the user must set it for the packages no declaration can name."""
    folders = [str(package.folder) for package in packages if package.declared == "environment"]
    before = [entry for entry in os.environ.get(VARIABLE, "").split(os.pathsep) if entry]
    return {VARIABLE: os.pathsep.join(dict.fromkeys([*folders, *before]))} if folders else {}


@contextlib.contextmanager
def found_packages(packages: Sequence[BesidePackage]) -> Iterator[None]:
    """The packages found beside the URDF resolvable for the duration of a block (``new``'s own
    reading and its check of the written spec), through ``ROS_PACKAGE_PATH``; then as before."""
    before = os.environ.get(VARIABLE)
    folders = [str(package.folder) for package in packages]
    with restored_after(VARIABLE):
        if folders:
            os.environ[VARIABLE] = os.pathsep.join([*folders, *([before] if before else [])])
        yield
