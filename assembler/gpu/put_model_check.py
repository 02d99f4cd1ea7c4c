"""``assembler build --target mjwarp``: hand the compiled model to MuJoCo Warp's own ``put_model``.

MuJoCo Warp is optional (the ``warp`` extra pulls warp-lang, ~150 MB), so it is imported here, on
use, through importlib; where it is absent the build says so in one line and goes on, and
``assembler lint --target mjwarp`` still reports what it would refuse, from the model alone.
"""

from __future__ import annotations

import contextlib
import importlib
import sys
from importlib.metadata import PackageNotFoundError, version

import mujoco

from assembler.errors import AssemblerError


def check_with_mujoco_warp(model: mujoco.MjModel, name: str) -> str:
    """One line saying MuJoCo Warp's put_model took ``model`` (or is not installed); an
    ``AssemblerError`` with its refusal when it does not take it."""
    try:
        warp = importlib.import_module("warp")
        warp.config.quiet = True  # no start-up banner (warp-lang 1.19 reads log_level instead)
        warp.config.log_level = getattr(warp, "LOG_WARNING", 30)
        engine = importlib.import_module("mujoco_warp")
    except ImportError:
        return (
            f"{name}: MuJoCo Warp is not installed, so its put_model did not run (pip install mujoco-warp); "
            f"assembler lint {name} --target mjwarp checks the model without it"
        )
    try:
        with contextlib.redirect_stdout(sys.stderr):
            engine.put_model(model)
    except (NotImplementedError, ValueError) as error:
        raise AssemblerError(
            f"{name}: MuJoCo Warp's put_model refuses the model: {error} (assembler lint {name} --target "
            "mjwarp names the element and the fix)"
        ) from None
    try:
        release = version("mujoco-warp")
    except PackageNotFoundError:  # an unpackaged checkout of MuJoCo Warp
        release = "(unpackaged)"
    return f"{name}: MuJoCo Warp {release} accepted the model (put_model)"
