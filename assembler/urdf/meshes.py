"""Mesh files MuJoCo cannot read (COLLADA ``.dae`` and other formats), converted to OBJ once.

MuJoCo reads STL, OBJ and MSH meshes. Vendors' URDFs often give their visual meshes as COLLADA;
MuJoCo refuses those outright. We convert such a file with trimesh (COLLADA through pycollada):
its scene graph's transforms are applied and its unit (``<unit meter>``) is turned into metres, as
ROS tools show it. The OBJ is kept in the cache's one store (``converted-meshes/``,
:mod:`assembler.cache.content`), named by the source file's digest and its own, and verified on
every use: an edited source gives a new file, an edited conversion is made again, and with the
cache off nothing is read from it. Without trimesh the file is reported once, with what to install.

MuJoCo's URDF import names each mesh after its file's stem; before MuJoCo 4.0 two files with one
stem (``visual/link1.stl`` and ``collision/link1.stl``, common in vendors' packages) became one mesh,
the first, for both geoms, in silence. A second file with a stem already taken is therefore given
to MuJoCo as a copy named ``<stem>-<digest>`` in the same folder as the conversions.
"""

from __future__ import annotations

import importlib.util
import shutil
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

from assembler.cache.content import CONVERTED, content_folder, kept_file
from assembler.cache.file_state import file_digest
from assembler.files.extras import install_command

READABLE_SUFFIXES: frozenset[str] = frozenset({".stl", ".obj", ".msh"})
"""Mesh formats MuJoCo reads itself."""


def _install_converter() -> str:
    return f"{install_command('urdf')}, which brings trimesh and pycollada"


class MeshConversionError(Exception):
    """A mesh could not be made readable; the message says which file and what to do."""


def converted_dir() -> Path:
    """Where converted meshes are kept (below the cache folder; this process's own with the cache off)."""
    return content_folder(CONVERTED)


def needs_conversion(path: Path) -> bool:
    """True for a mesh file whose format MuJoCo does not read."""
    return path.suffix.lower() not in READABLE_SUFFIXES


def importable(module: str) -> bool:
    """Whether ``module`` can be imported (a ``None`` in ``sys.modules`` blocks it, as Python does)."""
    if module in sys.modules:
        return sys.modules[module] is not None
    return importlib.util.find_spec(module) is not None


def converter_available() -> bool:
    """Whether trimesh can be imported."""
    return importable("trimesh")


def _kept(source: Path, suffix: str, make: Callable[[str], object]) -> Path:
    """The verified file made from ``source`` (by ``make(temporary path)`` when none is whole)."""
    return kept_file(converted_dir(), f"{source.stem}-{file_digest(source)}", suffix, make)


def renamed_copy(source: Path) -> Path:
    """A copy of ``source`` under a name no other mesh has (made once per content)."""
    return _kept(source, source.suffix, lambda temporary: shutil.copyfile(source, temporary))


def _convert(source: Path, target: str) -> None:
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
    mesh.export(target, file_type="obj", include_normals=False, include_texture=False)


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
    return _kept(source, ".obj", lambda temporary: _convert(source, temporary))
