"""How many of a geom's or site's three ``size`` numbers its type reads.

A sphere reads its radius, a capsule or cylinder its radius and half-length, a box or ellipsoid all
three. MuJoCo's XML writer writes only those, so a value in the others does not survive
``get_xml()`` (a reload takes the default there): a body's ``size_scale`` scales the numbers a type
reads and leaves the rest, and the model compiled and the model reloaded from its XML agree.
"""

from __future__ import annotations

import mujoco
import numpy as np
from numpy.typing import NDArray

READ_SIZES: dict[int, int] = {
    int(mujoco.mjtGeom.mjGEOM_SPHERE): 1,
    int(mujoco.mjtGeom.mjGEOM_CAPSULE): 2,
    int(mujoco.mjtGeom.mjGEOM_CYLINDER): 2,
    int(mujoco.mjtGeom.mjGEOM_ELLIPSOID): 3,
    int(mujoco.mjtGeom.mjGEOM_BOX): 3,
}
"""Primitive type -> the sizes it reads; every other type (plane, mesh, height field) keeps all three."""


def scaled_size(size: NDArray[np.float64], kind: int, factor: float) -> NDArray[np.float64]:
    """``size`` with the numbers a geom or site of type ``kind`` reads multiplied by ``factor``."""
    scaled = np.array(size, dtype=float)
    scaled[: READ_SIZES.get(int(kind), 3)] *= factor
    return scaled
