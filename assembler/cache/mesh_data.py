"""A mesh file as MuJoCo's own decoder reads it, in MuJoCo's binary ``.msh`` form.

``mujoco.MjSpec.from_file("link.obj")`` runs the OBJ (or STL) decoder plugin the compiler itself
uses and returns a spec whose one mesh holds the decoded arrays: vertices, normals, texture
coordinates and faces, before any of the compiler's processing (scaling, centring, alignment,
normals it computes). Written as ``.msh`` and handed to the compiler under the mesh's own file name
with ``content_type="model/vnd.mujoco.msh"``, they compile to a model identical in every byte of
``mj_saveModel`` (tests/cache/test_mesh_store.py): every mesh attribute (``scale``, ``refpos``,
``refquat``, ``inertia``, ``maxhullvert``, ``smoothnormal``) still applies, and the model's asset
paths still name the original file. Nothing here parses OBJ or STL text.

``.msh`` has one index per face corner, so a mesh whose normals or texture coordinates are indexed
apart from its vertices (many OBJ exporters write ``f v/vt/vn`` with three different indices) has
no exact ``.msh`` form: :func:`decode` says so and MuJoCo keeps reading that file itself.
"""

from __future__ import annotations

import functools
import os
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

MSH_CONTENT_TYPE = "model/vnd.mujoco.msh"

KINDS = {".obj": "model/obj", ".stl": "model/stl"}
"""File extensions whose meshes are decoded once and stored, with MuJoCo's content type for each."""


def mesh_kind(path: str, content_type: str) -> str | None:
    """The decoder a mesh's file goes through (``"model/obj"`` or ``"model/stl"``), or None when
    it is not one to store: no file, a path MuJoCo would resolve through ``meshdir`` (relative or
    not normalised: the in-memory file must carry the very name the compiler looks up), another
    format, or a ``content_type`` that overrides the extension."""
    if not path or not os.path.isabs(path) or os.path.normpath(path) != path:
        return None
    kind = KINDS.get(os.path.splitext(path)[1].lower())
    if kind is None or content_type not in ("", kind):
        return None
    return kind


def _array(values: Any, dtype: type[np.generic]) -> NDArray[Any]:
    # MuJoCo's vectors expose no buffer: element by element (about 0.1 us each) is the only way
    # out, which is why decoding happens off the compile's path (see mesh_swap).
    return np.fromiter(values, dtype=dtype, count=len(values))


def decode(path: str) -> bytes | None:
    """The ``.msh`` bytes of MuJoCo's decoding of the mesh file ``path``, or None when the decoded
    mesh has no exact ``.msh`` form. Raises ValueError when MuJoCo cannot decode the file."""
    spec = mujoco.MjSpec.from_file(path)
    if len(spec.meshes) != 1:
        return None
    mesh = spec.meshes[0]
    vertices = _array(mesh.uservert, np.float32)
    faces = _array(mesh.userface, np.int32)
    count = vertices.size // 3
    if count < 4 or vertices.size % 3 or faces.size == 0 or faces.size % 3:
        return None  # .msh needs 4 vertices and (here) faces; MuJoCo keeps the file
    parts = [vertices]
    for values, indices, width in (
        (mesh.usernormal, mesh.userfacenormal, 3),
        (mesh.usertexcoord, mesh.userfacetexcoord, 2),
    ):
        if len(values) == 0 and len(indices) == 0:
            parts.append(np.empty(0, np.float32))
        elif len(values) == width * count and np.array_equal(_array(indices, np.int32), faces):
            parts.append(_array(values, np.float32))
        else:
            return None  # indexed apart from the vertices
    normals, texcoords = parts[1], parts[2]
    header = np.array([count, normals.size // 3, texcoords.size // 2, faces.size // 3], np.int32)
    return b"".join(part.tobytes() for part in (header, vertices, normals, texcoords, faces))


@functools.lru_cache(maxsize=1)
def msh_supported() -> bool:
    """True when this MuJoCo compiles ``.msh`` data given in memory under another file's name
    (``MjSpec.assets`` and the ``.msh`` content type; the legacy format may be removed one day)."""
    tetrahedron = np.array([0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1], np.float32)
    faces = np.array([0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3], np.int32)
    data = np.array([4, 0, 0, 4], np.int32).tobytes() + tetrahedron.tobytes() + faces.tobytes()
    name = os.path.join(os.path.abspath(os.sep), "assembler-probe", "tetrahedron.obj")
    try:
        spec = mujoco.MjSpec()
        mesh = spec.add_mesh()
        mesh.name, mesh.file, mesh.content_type = "probe", name, MSH_CONTENT_TYPE
        spec.assets = {name: data}
        return bool(spec.compile().nmeshvert == 4)
    except (AttributeError, TypeError, ValueError):
        return False
