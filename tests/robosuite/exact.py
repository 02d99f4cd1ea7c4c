"""Two compiled models compared field by field, exactly: every array and number of ``MjModel``.

For models that should be the same model, element for element in the same order (a part read back
through robosuite's XML layer against our own compile of it). Names and file paths are left out:
robosuite prefixes names, and a part's files are named by where robosuite's reader found them.
"""

from __future__ import annotations

import mujoco
import numpy as np

NOT_COMPARED: frozenset[str] = frozenset(
    {"names", "names_map", "paths", "signature", "nnames", "nnames_map", "npaths", "nbuffer"}
)
"""Fields that hold names or paths, or count their bytes (nor are the ``name_*adr``/``*_pathadr`` offsets)."""


def _compared(field: str) -> bool:
    return not (field in NOT_COMPARED or field.startswith("name_") or field.endswith("pathadr"))


def differences(ours: mujoco.MjModel, theirs: mujoco.MjModel) -> list[str]:
    """One line per field whose value differs: the field, how many entries, the first of them."""
    found = []
    for field in sorted(dir(ours)):
        if field.startswith("_") or not _compared(field):
            continue
        mine, yours = getattr(ours, field), getattr(theirs, field, None)
        if isinstance(mine, (int, float)) and not isinstance(mine, bool):
            if mine != yours:
                found.append(f"{field}: {mine} != {yours}")
            continue
        if not isinstance(mine, np.ndarray) or not isinstance(yours, np.ndarray):
            continue
        if mine.shape != yours.shape:
            found.append(f"{field}: shape {mine.shape} != {yours.shape}")
            continue
        same = (
            (mine == yours) | (np.isnan(mine) & np.isnan(yours)) if mine.dtype.kind == "f" else mine == yours
        )
        if not np.all(same):
            first = tuple(np.argwhere(~same)[0])
            found.append(
                f"{field}: {int((~same).sum())} differ, first at {first}: {mine[first]!r} != {yours[first]!r}"
            )
    for field in ("timestep", "impratio", "density", "viscosity", "cone", "integrator", "gravity", "wind"):
        mine, yours = getattr(ours.opt, field), getattr(theirs.opt, field)
        if not np.array_equal(mine, yours):
            found.append(f"opt.{field}: {mine} != {yours}")
    return found
