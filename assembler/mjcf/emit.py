"""Write emitted MJCF to disk: atomically, and optionally as a self-contained bundle with its assets.

A failed build must never leave a partial file or clobber the user's previous output, so every
file is written to a temporary file in the target folder and moved into place with one rename.
"""

from __future__ import annotations

import hashlib
import os
import shutil
import tempfile
from pathlib import Path

import mujoco


def write_atomically(path: Path, content: str | bytes) -> None:
    """Write ``content`` to ``path`` so readers see the old file or the whole new one, never half."""
    path.parent.mkdir(parents=True, exist_ok=True)
    data = content.encode() if isinstance(content, str) else content
    handle, temporary = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(handle, "wb") as stream:
            stream.write(data)
            stream.flush()
            os.fsync(stream.fileno())
        os.replace(temporary, path)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _copy_atomically(source: Path, target: Path) -> None:
    handle, temporary = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=target.parent)
    os.close(handle)
    try:
        shutil.copyfile(source, temporary)
        os.replace(temporary, target)
    except BaseException:
        Path(temporary).unlink(missing_ok=True)
        raise


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def bundle(spec: mujoco.MjSpec, directory: Path, xml_name: str) -> Path:
    """Write ``directory/xml_name`` and copies of every asset file under ``directory/assets``.

    Asset paths in the XML become relative, so the folder can be moved or zipped. Two different
    files with one base name get distinct names (``link.stl``, ``link_1.stl``).
    """
    bundled = spec.copy()
    assets = directory / "assets"
    assets.mkdir(parents=True, exist_ok=True)
    placed: dict[str, str] = {}  # absolute source -> relative target
    taken: dict[str, str] = {}  # target name -> content digest

    def place(file: str) -> str:
        if not file:
            return file
        if file in placed:
            return placed[file]
        source = Path(file)
        digest = _digest(source)
        stem, suffix, n = source.stem, source.suffix, 0
        name = source.name
        while name in taken and taken[name] != digest:
            n += 1
            name = f"{stem}_{n}{suffix}"
        if name not in taken:
            _copy_atomically(source, assets / name)
            taken[name] = digest
        placed[file] = f"assets/{name}"
        return placed[file]

    for elements in (bundled.meshes, bundled.hfields, bundled.skins):
        for element in elements:
            element.file = place(element.file)
    for texture in bundled.textures:
        texture.file = place(texture.file)
        texture.cubefiles = [place(f) for f in texture.cubefiles]
    target = directory / xml_name
    write_atomically(target, bundled.to_xml())
    return target
