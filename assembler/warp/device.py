"""Writes into a MuJoCo Warp model in place, on its device: rows of some worlds, and the dampratios.

A batched field is one contiguous array of ``nworld`` rows; :func:`write_rows` copies the new rows
of some worlds (a small array, uploaded) into it with one kernel, so the model never goes through
the host. :func:`resolve_dampratios` gives each world's position actuators the ``biasprm[2]`` MuJoCo
4's compiler gives a ``dampratio`` (ratio x 2 sqrt(kp x reflected inertia), the inertia
``1 / (gear^2 (M^-1)_ii)`` at qpos0, which ``set_const`` leaves in ``dof_invweight0``).
"""

from __future__ import annotations

from typing import Any

import numpy as np
from numpy.typing import NDArray

from assembler.warp.loading import wp


@wp.kernel  # type: ignore[untyped-decorator]
def _scatter_rows(
    rows: wp.array2d(dtype=float),  # type: ignore[valid-type]
    worlds: wp.array(dtype=int),  # type: ignore[valid-type]
    target: wp.array2d(dtype=float),  # type: ignore[valid-type]
) -> None:
    i, j = wp.tid()
    target[worlds[i], j] = rows[i, j]


@wp.kernel  # type: ignore[untyped-decorator]
def _scatter_mapped(
    rows: wp.array2d(dtype=float),  # type: ignore[valid-type]
    worlds: wp.array(dtype=int),  # type: ignore[valid-type]
    columns: wp.array(dtype=int),  # type: ignore[valid-type]
    target: wp.array2d(dtype=float),  # type: ignore[valid-type]
) -> None:
    i, j = wp.tid()
    target[worlds[i], columns[j]] = rows[i, j]


@wp.kernel  # type: ignore[untyped-decorator]
def _dampratio_bias(
    actuators: wp.array(dtype=int),  # type: ignore[valid-type]
    dofs: wp.array(dtype=int),  # type: ignore[valid-type]
    ratios: wp.array(dtype=float),  # type: ignore[valid-type]
    gainprm: wp.array2d(dtype=float),  # type: ignore[valid-type]
    gear: wp.array2d(dtype=float),  # type: ignore[valid-type]
    invweight: wp.array2d(dtype=float),  # type: ignore[valid-type]
    biasprm: wp.array2d(dtype=float),  # type: ignore[valid-type]
) -> None:
    world, i = wp.tid()
    actuator = actuators[i]
    kp = gainprm[world % gainprm.shape[0], actuator * 10]
    g = gear[world % gear.shape[0], actuator * 6]
    inverse = invweight[world % invweight.shape[0], dofs[i]]
    biasprm[world % biasprm.shape[0], actuator * 10 + 2] = -ratios[i] * 2.0 * wp.sqrt(kp / (g * g * inverse))


def flat_view(array: Any) -> Any:
    """A batched model field as a 2D float array (rows, numbers per row), sharing its memory."""
    scalar = getattr(array.dtype, "_wp_scalar_type_", array.dtype)
    if scalar is not wp.float32 or not array.is_contiguous:
        raise TypeError(f"not a contiguous float32 field: {array.dtype}")
    rows = array.shape[0]
    per_row = array.size // rows * wp.types.type_size_in_bytes(array.dtype) // 4 if rows else 0
    return wp.array(ptr=array.ptr, dtype=wp.float32, shape=(rows, per_row), device=array.device, copy=False)


def write_rows(
    target: Any,
    worlds: NDArray[np.int64],
    rows: NDArray[np.float64],
    columns: NDArray[np.int64] | None = None,
) -> None:
    """``target[worlds[i]] = rows[i]`` on ``target``'s device (``rows``: one row per world given);
    with ``columns``, number j of a row goes to number ``columns[j]`` of the target's row (another
    model holding the same elements at other places)."""
    view = flat_view(target)
    flat = np.ascontiguousarray(rows.reshape(len(worlds), -1), dtype=np.float32)
    source = wp.array(flat, dtype=wp.float32, device=view.device)
    indices = wp.array(np.asarray(worlds, dtype=np.int32), dtype=wp.int32, device=view.device)
    if columns is None:
        wp.launch(_scatter_rows, dim=flat.shape, inputs=[source, indices, view], device=view.device)
        return
    where = wp.array(np.asarray(columns, dtype=np.int32), dtype=wp.int32, device=view.device)
    wp.launch(_scatter_mapped, dim=flat.shape, inputs=[source, indices, where, view], device=view.device)


def resolve_dampratios(model: Any, dampratio: dict[int, float], dofs: dict[int, int]) -> None:
    """Each world's ``biasprm[2]`` of the actuators in ``dampratio`` (actuator -> ratio; ``dofs``:
    actuator -> its joint's dof) from its ``dof_invweight0``, after ``set_const``."""
    if not dampratio:
        return
    actuators = sorted(dampratio)
    device = model.actuator_biasprm.device
    inputs = [
        wp.array(np.array(actuators, dtype=np.int32), dtype=wp.int32, device=device),
        wp.array(np.array([dofs[a] for a in actuators], dtype=np.int32), dtype=wp.int32, device=device),
        wp.array(
            np.array([dampratio[a] for a in actuators], dtype=np.float32), dtype=wp.float32, device=device
        ),
        flat_view(model.actuator_gainprm),
        flat_view(model.actuator_gear),
        flat_view(model.dof_invweight0),
        flat_view(model.actuator_biasprm),
    ]
    nworld = model.actuator_biasprm.shape[0]
    wp.launch(_dampratio_bias, dim=(nworld, len(actuators)), inputs=inputs, device=device)
