"""Which OpenGL backend MuJoCo's offscreen renderer uses, and a clear error when there is none.

MuJoCo reads ``MUJOCO_GL`` once, when ``mujoco`` is imported, and falls back to GLFW, which needs a
display. On a headless Linux machine (no ``DISPLAY`` or ``WAYLAND_DISPLAY``) with ``MUJOCO_GL``
unset we choose EGL, as ``MUJOCO_GL=egl`` would have, and reload MuJoCo's backend chooser so the
choice takes effect even though ``mujoco`` was imported long before.
"""

from __future__ import annotations

import importlib
import os
import sys
import warnings

import mujoco

from assembler.errors import AssemblerError

HEADLESS_BACKEND = "egl"
"""The backend chosen when ``MUJOCO_GL`` is unset and there is no display."""


class RenderError(AssemblerError):
    """MuJoCo cannot render here (no OpenGL backend), or the picture options are invalid."""


def _headless() -> bool:
    return sys.platform.startswith("linux") and not (
        os.environ.get("DISPLAY") or os.environ.get("WAYLAND_DISPLAY")
    )


def choose_backend() -> str:
    """Set ``MUJOCO_GL=egl`` when it is unset and there is no display; return the backend in use.

    MuJoCo's chooser is reloaded whenever ``MUJOCO_GL`` no longer says what it read at import:
    after our default, or after a library set it later (importing robosuite sets ``egl``).
    """
    if "MUJOCO_GL" not in os.environ and _headless():
        os.environ["MUJOCO_GL"] = HEADLESS_BACKEND
    wanted = os.environ.get("MUJOCO_GL", "").lower().strip()
    for name in ("mujoco.rendering.classic.gl_context", "mujoco.gl_context"):
        module = sys.modules.get(name)
        if module is not None and getattr(module, "_MUJOCO_GL", wanted) != wanted:
            importlib.reload(module)  # the Renderer looks GLContext up in it for every new instance
    return wanted or "glfw"


def new_renderer(model: mujoco.MjModel, width: int, height: int) -> mujoco.Renderer:
    """An offscreen renderer, or one :class:`RenderError` line saying what to set."""
    try:
        choose_backend()  # may reload MuJoCo's chooser, which refuses a MUJOCO_GL it does not know
        with warnings.catch_warnings():  # GLFW warns before failing; the error below says it all
            warnings.simplefilter("ignore")
            return mujoco.Renderer(model, height=height, width=width)
    except Exception as error:  # each backend fails differently (ImportError, RuntimeError, FatalError)
        reason = " ".join(str(error).split()) or type(error).__name__
        backend = os.environ.get("MUJOCO_GL", "").lower().strip() or "glfw"
        raise RenderError(
            f"cannot create an OpenGL context for offscreen rendering (MUJOCO_GL={backend}): {reason}. "
            "Set MUJOCO_GL=egl (GPU or Mesa EGL) or MUJOCO_GL=osmesa (software rendering), "
            "or run where a display is available"
        ) from None
