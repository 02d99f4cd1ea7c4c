"""Bundles: an emitted model with copies of its asset files, written only where they may go.

``build --bundle DIR`` writes ``DIR/NAME.xml`` and its assets under ``DIR/assets``; ``build -o FILE``
writes one file, and the assets it would name inside the cache folder (meshes converted from
COLLADA, which a ``cache clear`` or ``rm -rf`` of the cache removes) beside it, under
``FILE-assets/``: a written model never refers into the cache.

A bundle folder may already hold files. A bundle replaces only its own: each bundle writes a record,
``.assembler-bundle.json``, naming the files it wrote; a file that is there and that no earlier
record names is someone else's, and the bundle stops before writing anything, saying which file.
Re-running a build onto its own earlier bundle is the ordinary case and replaces its files.
"""

from __future__ import annotations

import hashlib
import json
import os
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterable
from pathlib import Path

from assembler.errors import AssemblerError
from assembler.files.cache_location import volatile_folders
from assembler.files.paths import display_path
from assembler.files.writing import (
    check_target,
    copy_atomically,
    make_folder,
    undone_on_failure,
    write_atomically,
)

RECORD = ".assembler-bundle.json"
"""The file in a bundle folder that names the files bundles wrote there."""

FILE_ATTRIBUTES: tuple[str, ...] = (
    "file",
    "fileright",
    "fileleft",
    "fileup",
    "filedown",
    "filefront",
    "fileback",
)
"""Attributes of MJCF asset elements that name a file (cube textures have six)."""

_UNSAFE_CHARACTERS = re.compile(r"[^A-Za-z0-9._-]")


def _safe_name(name: str) -> str:
    """``name`` as a plain file name in the bundle: letters, digits and ``. _ -``, not hidden.

    Asset names come from a stranger's MJCF; whatever they hold, the copy stays in the assets folder.
    """
    return _UNSAFE_CHARACTERS.sub("_", name).lstrip(".") or "asset"


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def own_files(directory: Path) -> set[str]:
    """The files (relative to ``directory``) that earlier bundles wrote there, by their record."""
    try:
        data = json.loads((directory / RECORD).read_text(encoding="utf-8"))
        return {str(name) for name in data["files"] if isinstance(name, str)}
    except (OSError, ValueError, KeyError, TypeError):
        return set()


def _refuse_foreign(record_folder: Path, targets: Iterable[Path]) -> list[str]:
    """The targets' names relative to ``record_folder``; stops when one is there and no bundle's
    record says it is a bundle's file, or is not a regular file."""
    own = own_files(record_folder)
    names = []
    for target in targets:
        check_target(target)
        name = target.relative_to(record_folder).as_posix()
        if os.path.lexists(target) and name not in own:
            raise AssemblerError(
                f"{display_path(target)} is there and is not a file an earlier bundle wrote (the "
                f"{RECORD} there does not name it); a bundle never replaces other files: move it away "
                "or choose another folder"
            )
        names.append(name)
    return names


def _assets_plan(root: ET.Element, assets: str, chosen: Iterable[str] | None) -> dict[str, str]:
    """Source file -> relative target (``assets/NAME``) of every asset file ``root`` names (only those
    in ``chosen`` when given); two different files of one name get ``NAME_1``..., one file copied once."""
    allowed = set(chosen) if chosen is not None else None
    placed: dict[str, str] = {}
    taken: dict[str, str] = {}  # target name -> content digest
    for section in root.iter("asset"):
        for element in section:
            for attribute in FILE_ATTRIBUTES:
                file = element.get(attribute)
                if not file or file in placed or (allowed is not None and file not in allowed):
                    continue
                source = Path(file)
                digest = _digest(source)
                name = _safe_name(source.name)
                stem, suffix, n = Path(name).stem, Path(name).suffix, 0
                while name in taken and taken[name] != digest:
                    n += 1
                    name = f"{stem}_{n}{suffix}"
                taken[name] = digest
                placed[file] = f"{assets}/{name}"
    return placed


def _rewrite(root: ET.Element, placed: dict[str, str]) -> str:
    for section in root.iter("asset"):
        for element in section:
            for attribute in FILE_ATTRIBUTES:
                file = element.get(attribute)
                if file and file in placed:
                    element.set(attribute, placed[file])
    return ET.tostring(root, encoding="unicode") + "\n"


def _write(
    xml_target: Path,
    root: ET.Element,
    placed: dict[str, str],
    assets: Path,
    record_folder: Path,
    bundled: bool,
) -> Path:
    """Write the assets (``placed``: source -> path relative to the XML's folder) and the XML, then
    the record in ``record_folder``; nothing is replaced that is not a bundle's own (the XML too when
    ``bundled``), and a failure removes what it created."""
    directory = xml_target.parent
    targets = [directory / relative for relative in dict.fromkeys(placed.values())]
    names = _refuse_foreign(record_folder, [*([xml_target] if bundled else []), *targets])
    with undone_on_failure(assets if placed or bundled else record_folder) as created:
        if placed or bundled:
            make_folder(assets)
            if not assets.resolve().is_relative_to(directory.resolve()):  # a link planted in the folder
                raise AssemblerError(
                    f"{display_path(assets)} leads out of {display_path(directory)}; remove it"
                )
        copied: set[str] = set()
        for source, relative in placed.items():
            if relative not in copied:
                if not os.path.lexists(directory / relative):
                    created.append(directory / relative)
                copy_atomically(Path(source), directory / relative)
                copied.add(relative)
        if not os.path.lexists(xml_target):
            created.append(xml_target)
        write_atomically(xml_target, _rewrite(root, placed))
        if names:
            own = sorted(own_files(record_folder) | set(names))
            write_atomically(record_folder / RECORD, json.dumps({"files": own}, indent=1) + "\n")
    return xml_target


def bundle_xml(xml: str, directory: Path, xml_name: str) -> Path:
    """Write the emitted MJCF ``xml`` as ``directory/xml_name`` and copies of every asset file it
    names under ``directory/assets``.

    Asset paths in the XML become relative, so the folder can be moved or zipped. Two different
    files with one base name get distinct names (``link.stl``, ``link_1.stl``). The paths are
    rewritten in the emitted text: MjSpec would try to open relative paths from the source folder.
    """
    if Path(xml_name).name != xml_name or xml_name in ("", ".", "..", RECORD):
        raise AssemblerError(f"bundle: expected a file name for the XML, got '{xml_name}'")
    root = ET.fromstring(xml)
    return _write(
        directory / xml_name, root, _assets_plan(root, "assets", None), directory / "assets", directory, True
    )


def write_model(xml: str, target: Path, volatile: Iterable[Path]) -> tuple[Path, int]:
    """Write the emitted MJCF ``xml`` to ``target``; the asset files it names below a ``volatile``
    folder (the cache) are copied beside it, under ``<name>-assets/``, and named relatively, so the
    file does not break when that folder is cleared. Returns the file and how many assets were copied."""
    roots = [Path(os.path.realpath(folder)) for folder in volatile]
    root = ET.fromstring(xml)
    inside = [
        file
        for section in root.iter("asset")
        for element in section
        for attribute in FILE_ATTRIBUTES
        if (file := element.get(attribute))
        and any(Path(os.path.realpath(file)).is_relative_to(folder) for folder in roots)
    ]
    if not inside:
        write_atomically(target, xml)
        return target, 0
    assets = f"{target.name}-assets"
    placed = _assets_plan(root, assets, inside)
    folder = target.parent / assets
    written = _write(target, root, placed, folder, folder, False)
    return written, len(set(placed.values()))


def save_model(xml: str, target: Path) -> Path:
    """Write ``xml`` to ``target`` as ``build -o`` does (:func:`write_model`): the files it names in the
    cache or scratch folders are copied beside it, so the saved model outlives them."""
    return write_model(xml, target, volatile_folders())[0]
