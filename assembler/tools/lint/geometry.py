"""Volumes and extents of a compiled model's geoms, to judge whether masses and inertias fit them."""

from __future__ import annotations

import math

import mujoco
import numpy as np
from numpy.typing import NDArray

FloatArray = NDArray[np.float64]

_GEOM = mujoco.mjtGeom


def mesh_volume(model: mujoco.MjModel, mesh: int) -> float:
    """Volume enclosed by a mesh (divergence theorem over its triangles; exact for closed meshes)."""
    first_vertex, first_face = model.mesh_vertadr[mesh], model.mesh_faceadr[mesh]
    vertices = model.mesh_vert[first_vertex : first_vertex + model.mesh_vertnum[mesh]]
    faces = model.mesh_face[first_face : first_face + model.mesh_facenum[mesh]]
    a, b, c = vertices[faces[:, 0]], vertices[faces[:, 1]], vertices[faces[:, 2]]
    return abs(float(np.einsum("ij,ij->i", a, np.cross(b, c)).sum()) / 6.0)


def geom_volume(model: mujoco.MjModel, geom: int) -> float:
    """A geom's volume in m^3 (0 for planes, height fields and other shapes without one)."""
    kind, size = model.geom_type[geom], model.geom_size[geom]
    if kind == _GEOM.mjGEOM_SPHERE:
        return 4.0 / 3.0 * math.pi * float(size[0]) ** 3
    if kind == _GEOM.mjGEOM_CAPSULE:
        return math.pi * float(size[0]) ** 2 * (4.0 / 3.0 * float(size[0]) + 2.0 * float(size[1]))
    if kind == _GEOM.mjGEOM_CYLINDER:
        return math.pi * float(size[0]) ** 2 * 2.0 * float(size[1])
    if kind == _GEOM.mjGEOM_BOX:
        return 8.0 * float(size[0] * size[1] * size[2])
    if kind == _GEOM.mjGEOM_ELLIPSOID:
        return 4.0 / 3.0 * math.pi * float(size[0] * size[1] * size[2])
    if kind == _GEOM.mjGEOM_MESH and model.geom_dataid[geom] >= 0:
        return mesh_volume(model, int(model.geom_dataid[geom]))
    return 0.0


def collides(model: mujoco.MjModel, geom: int) -> bool:
    """True if the geom can take part in contacts at all."""
    return bool(model.geom_contype[geom] or model.geom_conaffinity[geom])


def shape_volume(model: mujoco.MjModel, geoms: list[int]) -> float:
    """The volume of a rigid piece: the larger of its collision geoms' and its visual geoms' volumes.

    Collision geoms are often partial (a pad, a bumper) and visual ones sometimes absent, so the
    larger of the two is the better estimate of the piece's real shape.
    """
    colliding = sum(geom_volume(model, g) for g in geoms if collides(model, g))
    visual = sum(geom_volume(model, g) for g in geoms if not collides(model, g))
    return max(colliding, visual)


def reach(data: mujoco.MjData, model: mujoco.MjModel, point: FloatArray, geoms: list[int]) -> float:
    """How far the geoms extend from ``point`` (world frame): the radius of a sphere holding them all."""
    return max(
        (float(np.linalg.norm(data.geom_xpos[g] - point)) + float(model.geom_rbound[g]) for g in geoms),
        default=0.0,
    )
