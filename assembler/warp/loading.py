"""MuJoCo Warp, an optional dependency: imported here once, with the install line when it is missing.

``assembler.warp`` is the only package that needs it; the rest of the assembler never imports it.
"""

from __future__ import annotations

try:
    import mujoco_warp
    import warp as wp
    from mujoco_warp._src import types as warp_types
except ImportError as error:  # say how to get it, not only that it is missing
    raise ImportError(
        "assembler.warp needs MuJoCo Warp (Python >= 3.11): pip install -e '.[warp]' "
        "(or pip install 'robot-assembler[warp]')"
    ) from error

__all__ = ["mujoco_warp", "warp_types", "wp"]
