"""Mesh files MuJoCo cannot read (COLLADA ``.dae`` and other formats), converted to OBJ once.

MuJoCo reads STL, OBJ and MSH meshes. Vendors' URDFs often give their visual meshes as COLLADA;
MuJoCo refuses those outright. We convert such a file with trimesh (COLLADA through pycollada):
its scene graph's transforms are applied and its unit (``<unit meter>``) is turned into metres, as
ROS tools show it. The OBJ is written once into ``<cache folder>/converted-meshes/``, named by the
source file's content digest, so an edited source gives a new file and concurrent processes
agree on the name. Without trimesh the file is reported once, with what to install.

MuJoCo's URDF import names each mesh after its file's stem; before MuJoCo 4.0 two files with one
stem (``visual/link1.stl`` and ``collision/link1.stl``, common in vendors' packages) became one mesh,
the first, for both geoms, in silence. A second file with a stem already taken is therefore given
to MuJoCo as a copy named ``<stem>-<digest>`` in the same folder as the conversions.
"""

from __future__ import annotations

import hashlib
import importlib.util
import os
import shutil
import sys
import tempfile
from collections.abc import Callable
from pathlib import Path
from typing import Any

from assembler.cache.settings import cache_dir
from assembler.files.extras import install_command

READABLE_SUFFIXES: frozenset[str] = frozenset({".stl", ".obj", ".msh"})
"""Mesh formats MuJoCo reads itself."""


def _install_converter() -> str:
    return f"{install_command('urdf')}, which brings trimesh and pycollada"


_CHUNK = 1 << 20


class MeshConversionError(Exception):
    """A mesh could not be made readable; the message says which file and what to do."""


def converted_dir() -> Path:
    """Where converted meshes are kept (below the cache folder, beside the compiled models)."""
    return cache_dir() / "converted-meshes"


def needs_conversion(path: Path) -> bool:
    """True for a mesh file whose format MuJoCo does not read."""
    return path.suffix.lower() not in READABLE_SUFFIXES


def _digest(path: Path) -> str:
    digest = hashlib.blake2b(digest_size=16)
    with path.open("rb") as stream:
        while chunk := stream.read(_CHUNK):
            digest.update(chunk)
    return digest.hexdigest()


def importable(module: str) -> bool:
    """Whether ``module`` can be imported (a ``None`` in ``sys.modules`` blocks it, as Python does)."""
    if module in sys.modules:
        return sys.modules[module] is not None
    return importlib.util.find_spec(module) is not None


def converter_available() -> bool:
    """Whether trimesh can be imported."""
    return importable("trimesh")


def _digest_name(source: Path, suffix: str) -> Path:
    return converted_dir() / f"{source.stem}-{_digest(source)}{suffix}"


def _write_atomically(target: Path, write: Callable[[str], object]) -> None:
    """``write(temporary path)``, then the file appears whole under ``target`` (another process sees
    all of it or nothing)."""
    target.parent.mkdir(parents=True, exist_ok=True)
    descriptor, temporary = tempfile.mkstemp(dir=target.parent, suffix=target.suffix + ".tmp")
    os.close(descriptor)
    try:
        write(temporary)
        os.replace(temporary, target)
    finally:
        Path(temporary).unlink(missing_ok=True)


def renamed_copy(source: Path) -> Path:
    """A copy of ``source`` under a name no other mesh has (made once per content)."""
    target = _digest_name(source, source.suffix)
    if not target.is_file():
        _write_atomically(target, lambda temporary: shutil.copyfile(source, temporary))
    return target


def _convert(source: Path, target: Path) -> None:
    import trimesh  # the optional extra: imported only when a mesh needs it

    try:
        scene: Any = trimesh.load(str(source), force="scene")  # a trimesh.Scene
    except Exception as error:  # trimesh raises many kinds; each means "this file cannot be read"
        raise MeshConversionError(f"{source}: trimesh cannot read it ({error})") from None
    if scene.units not in (None, "m", "meter", "meters"):
        scene = scene.convert_units("meters")  # COLLADA <unit meter="0.001"> and the like
    if not scene.geometry:
        raise MeshConversionError(f"{source}: the file holds no triangles; give the link another mesh")
    mesh = scene.to_mesh()
    # No normals: MuJoCo computes its own, and trimesh's take minutes for Panda's meshes without scipy.
    _write_atomically(
        target,
        lambda temporary: mesh.export(
            temporary, file_type="obj", include_normals=False, include_texture=False
        ),
    )


def readable_mesh(source: Path) -> Path:
    """``source`` if MuJoCo reads it, else its OBJ conversion (made now if not made before)."""
    if not needs_conversion(source):
        return source
    if source.suffix.lower() == ".dae" and not importable("collada"):
        missing = "trimesh and pycollada" if not converter_available() else "pycollada"
        raise MeshConversionError(
            f"{source}: MuJoCo cannot read {source.suffix} meshes (only STL, OBJ, MSH) and {missing} "
            f"to convert it are not installed; {_install_converter()}, or convert it to STL/OBJ yourself"
        )
    if not converter_available():
        raise MeshConversionError(
            f"{source}: MuJoCo cannot read {source.suffix} meshes (only STL, OBJ, MSH) and trimesh to "
            f"convert it is not installed; {_install_converter()}, or convert it to STL/OBJ yourself"
        )
    target = _digest_name(source, ".obj")
    if not target.is_file():
        _convert(source, target)
    return target
