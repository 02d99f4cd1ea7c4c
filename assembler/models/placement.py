"""Where a robot stands: robosuite's placement API on a robot part (its dimensions, from its spec and
its base, and the root's pose set by ``set_base_xpos``/``set_base_ori``), kept apart from building.

robosuite's environments place a robot through these names (``top_offset``, ``bottom_offset``,
``horizontal_radius``, ``base_xpos_offset``, ``set_base_xpos``, ``set_base_ori``); they read the
spec and the base, never the compiled model, so placing costs no build.
"""

from __future__ import annotations

from typing import Any, ClassVar

import mujoco
import numpy as np

from assembler.errors import AssemblerError
from assembler.models.bases import RobotBaseModel
from assembler.models.part import FloatArray, PartModel
from assembler.spec.schema import RobotSpec


def euler_to_quat(rpy: FloatArray) -> FloatArray:
    """(w, x, y, z) of the rotation Rx(roll) Ry(pitch) Rz(yaw): robosuite's ``set_base_ori`` goes through
    ``transform_utils.euler2mat``, which builds that product (rotations about the moving x, y', z'')."""
    quat = np.zeros(4)
    mujoco.mju_euler2Quat(quat, np.asarray(rpy, dtype=float), "xyz")
    return quat


class PlacedPart(PartModel):
    """A robot part with robosuite's placement API; :class:`~assembler.models.RobotModel` builds it."""

    in_registry = False
    spec: ClassVar[RobotSpec]

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self.base: RobotBaseModel | None = None
        self._root_pos: FloatArray | None = None
        self._root_quat: FloatArray | None = None
        self._mjspec: mujoco.MjSpec | None = None

    # ----- dimensions ---------------------------------------------------------------------

    @property
    def base_xpos_offset(self) -> dict[str, Any]:
        """Per arena, a function of the arena's variables (``table_length=...``) giving the offset."""

        def offset(arena: str) -> Any:
            return lambda **variables: np.array(self.spec.resolve_base_xpos_offset(arena, **variables))

        return {arena: offset(arena) for arena in self.spec.base_xpos_offset}

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the robot's root to its top (metres)."""
        return np.array(self.spec.top_offset, dtype=float)

    @property
    def _horizontal_radius(self) -> float:
        return self.spec.horizontal_radius

    @property
    def horizontal_radius(self) -> float:
        """Footprint radius (metres); the base's, if larger."""
        if self.base is None:
            return self._horizontal_radius
        return max(self._horizontal_radius, self.base.horizontal_radius)

    @property
    def base_offset(self) -> FloatArray:
        """The root body's position as the MJCF writes it (robosuite's ``_base_offset``)."""
        return np.array(self.source.pristine.body(self.root_name).pos, dtype=float)

    @property
    def bottom_offset(self) -> FloatArray:
        """Vector from the root body to the bottom of the robot (and of its base, when it has one)."""
        if self.base is None:
            if self.spec.bottom_offset is not None:
                return np.array(self.spec.bottom_offset, dtype=float)
            return self.base_offset
        return self.base.bottom_offset - self.base.top_offset + self.base_offset

    # ----- placement and joints -----------------------------------------------------------

    def set_base_xpos(self, pos: FloatArray) -> None:
        """Place the robot so that its bottom is at ``pos`` (x, y, z in metres)."""
        position = np.asarray(pos, dtype=float)
        if position.shape != (3,) or not np.all(np.isfinite(position)):
            raise AssemblerError(f"set_base_xpos: expected 3 finite numbers, got {pos!r}")
        self._root_pos = position - self.bottom_offset
        if self._mjspec is not None:
            self._apply_placement(self._mjspec)

    def set_base_ori(self, rot: FloatArray) -> None:
        """Orient the robot by (roll, pitch, yaw) in radians as robosuite does: Rx(roll) Ry(pitch) Rz(yaw)."""
        angles = np.asarray(rot, dtype=float)
        if angles.shape != (3,) or not np.all(np.isfinite(angles)):
            raise AssemblerError(f"set_base_ori: expected 3 finite angles, got {rot!r}")
        self._root_quat = euler_to_quat(angles)
        if self._mjspec is not None:
            self._apply_placement(self._mjspec)

    def place_as(self, other: PlacedPart) -> None:
        """Place this robot where ``other`` was placed (its ``set_base_xpos``/``set_base_ori``)."""
        self._root_pos, self._root_quat = other._root_pos, other._root_quat
        if self._mjspec is not None:
            self._apply_placement(self._mjspec)

    def _apply_placement(self, assembly: mujoco.MjSpec) -> None:
        root = assembly.body(self.root_body)
        if self._root_pos is not None:
            root.pos = self._root_pos
        if self._root_quat is not None:
            root.quat = self._root_quat
