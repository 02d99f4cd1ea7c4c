"""Auto-framing: where a free camera must stand so the robot fills the picture, for each named view.

The camera looks at the robot from a fixed direction (azimuth and elevation in MuJoCo's free-camera
convention) and moves back just far enough that every corner of the robot's geom boxes projects
inside the frame, with a small margin; the look-at point is then shifted so the projected robot is
centred. Perspective makes both depend on each other, so the two steps are repeated a few times.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

VIEWS: dict[str, tuple[float, float]] = {
    "front": (180.0, -8.0),
    "side": (90.0, -8.0),
    "top": (180.0, -90.0),
    "iso": (135.0, -25.0),
}
"""View name -> (azimuth, elevation) in degrees. Robots face +x, so "front" looks at them along -x."""

FILL = 0.9
"""Fraction of the frame's width or height the robot may fill (the rest is margin)."""


@dataclass(frozen=True)
class Framing:
    """A free camera's pose: what it looks at, from how far, from which direction."""

    lookat: NDArray[np.float64]
    distance: float
    azimuth: float
    elevation: float

    def camera(self) -> mujoco.MjvCamera:
        """The pose as MuJoCo's free camera."""
        camera = mujoco.MjvCamera()
        camera.type = mujoco.mjtCamera.mjCAMERA_FREE
        camera.lookat[:] = self.lookat
        camera.distance = self.distance
        camera.azimuth = self.azimuth
        camera.elevation = self.elevation
        return camera


def camera_axes(azimuth: float, elevation: float) -> tuple[NDArray[np.float64], ...]:
    """Forward, right and up unit vectors of a free camera (as ``mjv_updateCamera`` computes them)."""
    az, el = math.radians(azimuth), math.radians(elevation)
    forward = np.array([math.cos(el) * math.cos(az), math.cos(el) * math.sin(az), math.sin(el)])
    up = np.array([-math.sin(el) * math.cos(az), -math.sin(el) * math.sin(az), math.cos(el)])
    return forward, np.cross(forward, up), up


def frame(
    points: NDArray[np.float64], view: str, fovy_degrees: float, aspect: float, iterations: int = 4
) -> Framing:
    """The camera for ``view`` that shows all ``points`` (n, 3), centred, filling ``FILL`` of the frame."""
    azimuth, elevation = VIEWS[view]
    forward, right, up = camera_axes(azimuth, elevation)
    tan_y = math.tan(math.radians(fovy_degrees) / 2) * FILL
    tan_x = tan_y * aspect
    lookat = (points.min(axis=0) + points.max(axis=0)) / 2

    def fit(lookat: NDArray[np.float64]) -> tuple[float, NDArray[np.float64]]:
        relative = points - lookat
        x, y, z = relative @ right, relative @ up, relative @ forward
        distance = float(max(np.max(np.abs(x) / tan_x - z), np.max(np.abs(y) / tan_y - z), 1e-3))
        u, v = x / (distance + z), y / (distance + z)  # tangents of the angles off the optical axis
        shift = (right * (u.min() + u.max()) + up * (v.min() + v.max())) / 2 * distance
        return distance, lookat + shift

    for _ in range(iterations):
        _, lookat = fit(lookat)
    distance, _ = fit(lookat)
    return Framing(lookat=lookat, distance=distance, azimuth=azimuth, elevation=elevation)
