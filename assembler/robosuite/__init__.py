"""Spec robots, grippers and bases in robosuite's environments.

>>> import assembler.robosuite          # our specs enter robosuite's registries when robosuite loads
>>> import robosuite
>>> env = robosuite.make("Lift", robots="Sparrow7", has_renderer=False, use_camera_obs=False)

Importing this package costs nothing and imports no robosuite: the bridge (:mod:`.bridge`) is
imported when robosuite is, before or after this package, or when one of the functions below is
first called. So :mod:`.conventions` (what robosuite asks of a spec, for ``assembler lint``) and the
start-up hook (:mod:`.hook`) live here without making robosuite a dependency of either.
"""

from __future__ import annotations

import importlib
import sys
from typing import Any

from assembler.robosuite.hook import when_robosuite_loads

__all__ = ["register", "register_experiment", "registered", "replace_robosuite", "replaced"]


def _bridge() -> Any:
    return importlib.import_module("assembler.robosuite.bridge")


def __getattr__(name: str) -> Any:
    """The bridge's functions, importing robosuite (and registering our specs) on first use."""
    if name in __all__:
        return getattr(_bridge(), name)
    raise AttributeError(f"module 'assembler.robosuite' has no attribute '{name}'")


def _bridge_unless_importing_ours() -> None:
    """The bridge, when robosuite loads; unless one of this package's own modules loaded robosuite
    while it is itself being imported (``import assembler.robosuite.autoload`` first): the bridge
    needs that module whole, so it comes on the first use of a function above instead."""
    if any(
        name.startswith(f"{__name__}.") and getattr(getattr(module, "__spec__", None), "_initializing", False)
        for name, module in list(sys.modules.items())
    ):
        return
    _bridge()


when_robosuite_loads(_bridge_unless_importing_ours)
