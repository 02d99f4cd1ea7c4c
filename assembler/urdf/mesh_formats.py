"""Mesh files MuJoCo cannot read (COLLADA ``.dae``), converted to OBJ once; the formats allowed at all.

MuJoCo reads STL, OBJ and MSH meshes. Vendors' URDFs often give their visual meshes as COLLADA;
MuJoCo refuses those outright. Mesh formats are an allow-list: these four, nothing else (trimesh
would open dozens more, and decompress ``.zip``, ``.bz2`` or ``.tar.*`` archives without a bound).
A COLLADA file is read through one bounded read (:data:`assembler.files.limits.MAX_DAE_BYTES`),
refused if it is an archive or declares a DTD, and handed to trimesh as bytes, so trimesh opens
no file itself (no texture, nothing a crafted file names). The conversion (COLLADA through pycollada):
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
import io
import shutil
import sys
from collections.abc import Callable
from pathlib import Path
from typing import Any

import numpy as np

from assembler.cache.content import CONVERTED, content_folder, kept_file
from assembler.cache.file_state import buffer_digest, file_digest
from assembler.errors import MjcfError
from assembler.files.extras import install_command
from assembler.files.inputs import note_inputs
from assembler.files.limits import MAX_DAE_BYTES
from assembler.files.paths import confine, display_path
from assembler.files.plain_xml import check_plain_xml
from assembler.files.regular import FileTooLarge, read_bounded

READABLE_SUFFIXES: frozenset[str] = frozenset({".stl", ".obj", ".msh"})
"""Mesh formats MuJoCo reads itself."""

CONVERTED_SUFFIXES: frozenset[str] = frozenset({".dae"})
"""Mesh formats converted to OBJ with trimesh (COLLADA through pycollada)."""

ALLOWED_FORMATS = "STL, OBJ, MSH (read by MuJoCo) or DAE (COLLADA, converted to OBJ)"

ARCHIVE_SUFFIXES: frozenset[str] = frozenset(
    {".zip", ".zae", ".gz", ".tgz", ".bz2", ".tbz2", ".xz", ".txz", ".lzma", ".zst", ".7z", ".rar", ".tar"}
)
"""Archives trimesh would open (and decompress) if given one; named as such in the refusal."""

ARCHIVE_MAGIC: tuple[bytes, ...] = (
    b"PK\x03\x04",
    b"\x1f\x8b",
    b"BZh",
    b"\xfd7zXZ\x00",
    b"7z\xbc\xaf",
    b"\x28\xb5\x2f\xfd",
)
"""The first bytes of zip, gzip, bzip2, xz, 7z and zstd files: a ``.dae`` that starts so is an archive."""


def _install_converter() -> str:
    return f"{install_command('urdf')}, which brings trimesh and pycollada"


class MeshConversionError(Exception):
    """A mesh could not be made readable; the message says which file and what to do."""


def converted_dir() -> Path:
    """Where converted meshes are kept (below the cache folder; this process's own with the cache off)."""
    return content_folder(CONVERTED)


def check_mesh_format(path: Path, shown: str) -> None:
    """Refuse a mesh whose suffix is not an allowed format (one line naming ``shown`` and the formats);
    looked at before the file is, so the answer says nothing about whether it exists."""
    suffixes = [suffix.lower() for suffix in path.suffixes]
    suffix = path.suffix.lower()
    if suffix in READABLE_SUFFIXES or suffix in CONVERTED_SUFFIXES:
        return
    archive = next((i for i, s in enumerate(suffixes) if s in ARCHIVE_SUFFIXES), None)
    what = (
        f"an archive ({''.join(suffixes[archive:])})"
        if archive is not None
        else f"'{suffix}'"
        if suffix
        else "a file without a suffix"
    )
    raise MeshConversionError(f"{shown}: {what} is not a mesh format read here; a mesh is {ALLOWED_FORMATS}")


def needs_conversion(path: Path) -> bool:
    """True for a mesh file whose format MuJoCo does not read."""
    return path.suffix.lower() not in READABLE_SUFFIXES


def _read_dae(source: Path) -> bytes:
    """The COLLADA file's bytes, read once and bounded; an archive or a DTD is refused."""
    try:
        data = read_bounded(source, MAX_DAE_BYTES)
    except FileTooLarge as error:
        raise MeshConversionError(f"{display_path(source)}: {error.strerror} for a mesh") from None
    except OSError as error:
        raise MeshConversionError(
            f"{display_path(source)}: cannot read it ({error.strerror or error})"
        ) from None
    if data.startswith(ARCHIVE_MAGIC):
        raise MeshConversionError(
            f"{display_path(source)}: an archive, not a COLLADA file; a mesh is {ALLOWED_FORMATS}"
        )
    check_plain_xml(data, display_path(source), MeshConversionError)
    return data


def importable(module: str) -> bool:
    """Whether ``module`` can be imported (a ``None`` in ``sys.modules`` blocks it, as Python does)."""
    if module in sys.modules:
        return sys.modules[module] is not None
    return importlib.util.find_spec(module) is not None


def converter_available() -> bool:
    """Whether trimesh can be imported."""
    return importable("trimesh")


def _kept(source: Path, digest: str, suffix: str, make: Callable[[str], object]) -> Path:
    """The verified file made from ``source`` (content ``digest``), by ``make(temporary path)`` when
    none is whole, in the one store (:mod:`assembler.cache.content`)."""
    return kept_file(converted_dir(), f"{source.stem}-{digest}", suffix, make)


def _confined(made: Path) -> Path:
    """A file made in the conversions' folder, through the one door every file read passes (a link
    placed there leading out is refused like any other)."""
    return confine(made, [converted_dir()], "converted mesh ", MjcfError)


def renamed_copy(source: Path) -> Path:
    """A copy of ``source`` under a name no other mesh has (made once per content)."""
    made = _kept(
        source, file_digest(source), source.suffix, lambda temporary: shutil.copyfile(source, temporary)
    )
    return _confined(made)


def _convert(source: Path, data: bytes, target: str) -> None:
    import trimesh  # the optional extra: imported only when a mesh needs it

    try:  # bytes, not a path: trimesh then has no folder to resolve a texture or another file in
        scene: Any = trimesh.load(io.BytesIO(data), file_type="dae", force="scene")  # a trimesh.Scene
    except Exception as error:  # trimesh raises many kinds; each means "this file cannot be read"
        raise MeshConversionError(f"{display_path(source)}: trimesh cannot read it ({error})") from None
    if not scene.geometry:
        raise MeshConversionError(
            f"{display_path(source)}: the file holds no triangles; give the link another mesh"
        )
    try:
        with np.errstate(all="ignore"):  # a NaN unit or transform: refused below, not warned about
            if scene.units not in (None, "m", "meter", "meters"):
                scene = scene.convert_units("meters")  # COLLADA <unit meter="0.001"> and the like
            mesh = scene.to_mesh()
    except Exception as error:  # numpy's and trimesh's errors on a unit of 0, a singular transform, ...
        raise MeshConversionError(f"{display_path(source)}: trimesh cannot convert it ({error})") from None
    if not np.isfinite(mesh.vertices).all():
        raise MeshConversionError(
            f"{display_path(source)}: its coordinates are not finite numbers once in metres (a NaN or "
            "infinite <unit>, transform or vertex); fix the file"
        )
    # No normals: MuJoCo computes its own, and trimesh's take minutes for Panda's meshes without scipy.
    mesh.export(target, file_type="obj", include_normals=False, include_texture=False)


def readable_mesh(source: Path) -> Path:
    """``source`` if MuJoCo reads it, else its OBJ conversion (made now if not made before)."""
    shown = display_path(source)
    check_mesh_format(source, shown)  # the file the name resolved to: a link may change the suffix
    note_inputs([source])  # read here or by MuJoCo: no output may replace it
    if not needs_conversion(source):
        return source
    if source.suffix.lower() == ".dae" and not importable("collada"):
        missing = "trimesh and pycollada" if not converter_available() else "pycollada"
        raise MeshConversionError(
            f"{shown}: MuJoCo cannot read {source.suffix} meshes (only STL, OBJ, MSH) and {missing} "
            f"to convert it are not installed; {_install_converter()}, or convert it to STL/OBJ yourself"
        )
    if not converter_available():
        raise MeshConversionError(
            f"{shown}: MuJoCo cannot read {source.suffix} meshes (only STL, OBJ, MSH) and trimesh to "
            f"convert it is not installed; {_install_converter()}, or convert it to STL/OBJ yourself"
        )
    data = _read_dae(source)
    made = _kept(source, buffer_digest(data), ".obj", lambda temporary: _convert(source, data, temporary))
    return _confined(made)
