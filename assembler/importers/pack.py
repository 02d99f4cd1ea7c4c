"""``assembler new MODEL --pack DIR``: the spec written into a spec pack others ``pip install``.

The pack is a folder holding a ``pyproject.toml`` (written when there is none) that declares the
entry point ``robot_assembler.specs`` (:mod:`assembler.registry.packs`), and an importable package
named after the folder (``acme-robots/`` -> ``acme_robots``) with ``specs/`` and ``assets/``. The
vendor's file and every file it reads (includes, meshes, textures) are copied under
``assets/<file's stem>/`` keeping their layout, with the licence files found beside them or in the
folders above them up to their common folder; the spec names the copy as
``package://<package>/assets/...``, so it reads the same files wherever the pack is installed. The
vendor's files are never changed. A URDF that names its meshes by ``package://`` cannot be copied
as it is (the names would lead back to the vendor's package): it is refused with what to do.
"""

from __future__ import annotations

import contextlib
import importlib
import os
import re
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

from assembler.cache.dependencies import asset_files
from assembler.errors import AssemblerError
from assembler.files.paths import display_path
from assembler.files.writing import copy_atomically, make_folder, write_atomically
from assembler.importers import Kind, NewSpec, new_spec, snake_case, write_spec_and_jaws
from assembler.importers.reading import check_model_path, read_model_file

LICENCE = re.compile(r"^(licen[cs]e|copying|notice)([.-].*)?$", re.IGNORECASE)
"""File names that hold a licence or its notices."""

PYPROJECT = """\
[build-system]
requires = ["hatchling>=1.21"]
build-backend = "hatchling.build"

[project]
name = "{distribution}"
version = "0.1.0"
description = "Robot specs for robot-assembler."

[project.entry-points."robot_assembler.specs"]
{package} = "{package}:specs"

[tool.hatch.build.targets.wheel]
packages = ["{package}"]
"""


@dataclass(frozen=True)
class WrittenPack:
    """What ``new --pack`` wrote."""

    spec: NewSpec
    spec_path: Path
    package: str
    copied: int
    """How many vendor files were copied (the model file, what it reads, the licences)."""
    licences: tuple[Path, ...]
    pyproject_written: bool


def package_name(folder: Path) -> str:
    """A pack folder's importable package: its name in snake case (``acme-robots`` -> ``acme_robots``)."""
    name = re.sub(r"[^0-9A-Za-z_]", "_", folder.resolve().name).lower()
    if not name.isidentifier():
        raise AssemblerError(
            f"--pack {display_path(folder)}: its name makes no Python package name ('{name}'); "
            "name the folder with letters, digits, - and _, starting with a letter"
        )
    return name


@contextlib.contextmanager
def importable(folder: Path) -> Iterator[None]:
    """``folder`` on the import path for a block: the pack's package is found as once installed."""
    sys.path.insert(0, str(folder))
    importlib.invalidate_caches()
    try:
        yield
    finally:
        sys.path.remove(str(folder))
        importlib.invalidate_caches()


def _read_files(model_path: Path) -> list[Path]:
    """The vendor's file and every file reading it reads, resolved."""
    model = read_model_file(model_path)
    if model.format == "urdf" and "package://" in model.path.read_text(errors="replace"):
        raise AssemblerError(
            f"{display_path(model.path)}: names its meshes by package://, which would lead back to the "
            "vendor's package from a copy; write the spec without --pack, or copy the package with its URDF"
        )
    files = [Path(path).resolve() for path, _, _ in model.source.files]
    files += [Path(path).resolve() for path in asset_files(model.source.new_spec())]
    return list(dict.fromkeys([model.path, *files]))


def _licences(files: list[Path], root: Path) -> list[Path]:
    """Licence files in the folders of ``files`` and above them, up to and including ``root``."""
    folders: set[Path] = set()
    for file in files:
        for folder in [file.parent, *file.parent.parents]:
            folders.add(folder)
            if folder == root:
                break
    found = [
        path
        for folder in sorted(folders)
        for path in sorted(folder.iterdir())
        if path.is_file() and LICENCE.match(path.name)
    ]
    return list(dict.fromkeys(found))


def write_pack(
    model_path: Path, pack: Path, kind: Kind | None = None, force: bool = False, strict: bool = False
) -> WrittenPack:
    """Copy the vendor's files into the pack at ``pack`` and write the spec there (see the module)."""
    model_path = check_model_path(model_path)
    package = package_name(pack)
    files = _read_files(model_path)
    root = Path(os.path.commonpath([str(file.parent) for file in files]))
    licences = _licences(files, root)
    assets = pack / package / "assets" / model_path.stem
    copies = [(file, assets / file.relative_to(root)) for file in files]
    copies += [  # a licence above the files' common folder goes to the top of the copy
        (licence, assets / (licence.relative_to(root) if licence.is_relative_to(root) else licence.name))
        for licence in licences
    ]
    for _, target in copies:
        if target.exists() and not force:
            raise AssemblerError(f"{display_path(target)}: exists; keep it, or give --force to replace it")
    for source, target in copies:
        make_folder(target.parent)
        copy_atomically(source, target)
    for folder in (pack / package, pack / package / "specs"):
        make_folder(folder)
    if not (pack / package / "__init__.py").exists():
        write_atomically(pack / package / "__init__.py", "")
    pyproject = pack / "pyproject.toml"
    written_pyproject = not pyproject.exists()
    if written_pyproject:
        distribution = package.replace("_", "-")
        write_atomically(pyproject, PYPROJECT.format(distribution=distribution, package=package))
    copied_model = assets / model_path.resolve().relative_to(root)
    with importable(pack.resolve()):
        written = new_spec(copied_model, pack / package / "specs" / "new.yaml", kind, strict)
    target = pack / package / "specs" / f"{snake_case(written.name)}.yaml"
    if target.exists() and not force:
        raise AssemblerError(f"{display_path(target)}: exists; keep it, or give --force to replace it")
    write_spec_and_jaws(written, target, force)
    return WrittenPack(written, target, package, len(copies), tuple(licences), written_pyproject)
