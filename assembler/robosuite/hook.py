"""Running the bridge when robosuite loads, and the start-up hook that does it in scripts nobody edits.

``python -m assembler.robosuite --install-hook`` writes a ``.pth`` file whose one line imports
:mod:`assembler.robosuite` at interpreter start, but only when ``ASSEMBLER_ROBOSUITE_SPECS`` or
``ASSEMBLER_ROBOSUITE_EXPERIMENT`` is set. That imports no robosuite: it waits for the process to
import robosuite, then imports the bridge (which registers what the variables name).
A process that never imports robosuite pays one import-system lookup. Importing robosuite at start
instead would run in every Python process, including the ones robosuite's own imports spawn.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
from collections.abc import Callable, Sequence
from types import ModuleType
from typing import Any

VARIABLES: tuple[str, ...] = ("ASSEMBLER_ROBOSUITE_SPECS", "ASSEMBLER_ROBOSUITE_EXPERIMENT")
"""The hook does anything only when one of these is set."""

PTH_LINE = (
    "import os, sys; ("
    + " or ".join(f"os.environ.get('{name}')" for name in VARIABLES)
    + ") and __import__('assembler.robosuite.hook')\n"
)
"""The line of the ``.pth`` file (site runs lines that start with ``import``); the parentheses matter:
``a or b and c`` is ``a or (b and c)``, which never imports the hook when the first variable is set."""


class AfterRobosuite(importlib.abc.MetaPathFinder):
    """Finds nothing itself; when robosuite is imported, runs its callbacks after robosuite has loaded."""

    def __init__(self) -> None:
        self.callbacks: list[Callable[[], object]] = []

    def find_spec(self, name: str, path: Sequence[str] | None, target: ModuleType | None = None) -> Any:
        if name != "robosuite":
            return None
        sys.meta_path.remove(self)
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is None or spec.loader is None:
            return spec
        loader = spec.loader
        load = loader.exec_module
        callbacks = self.callbacks

        def exec_module(module: ModuleType) -> None:
            load(module)
            for callback in callbacks:
                callback()

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


def when_robosuite_loads(callback: Callable[[], object]) -> None:
    """Call ``callback`` now if robosuite is imported, else right after the process imports it."""
    if "robosuite" in sys.modules:
        callback()
        return
    finder = next((f for f in sys.meta_path if isinstance(f, AfterRobosuite)), None)
    if finder is None:
        finder = AfterRobosuite()
        sys.meta_path.insert(0, finder)
    if callback not in finder.callbacks:
        finder.callbacks.append(callback)
