"""The start-up hook that registers spec robots with robosuite in scripts nobody edits.

``python -m assembler.robosuite --install-hook`` writes a ``.pth`` file whose one line imports this
module at interpreter start, but only when ``ASSEMBLER_ROBOSUITE_SPECS`` or
``ASSEMBLER_ROBOSUITE_EXPERIMENT`` is set. It imports nothing itself: it waits for the process to
import robosuite, then imports :mod:`assembler.robosuite` (which registers what the variables name).
A process that never imports robosuite pays one import-system lookup. Importing robosuite at start
instead would run in every Python process, including the ones robosuite's own imports spawn.
"""

from __future__ import annotations

import importlib
import importlib.abc
import importlib.machinery
import sys
from collections.abc import Sequence
from types import ModuleType
from typing import Any

VARIABLES: tuple[str, ...] = ("ASSEMBLER_ROBOSUITE_SPECS", "ASSEMBLER_ROBOSUITE_EXPERIMENT")
"""The hook does anything only when one of these is set."""

PTH_LINE = (
    "import os, sys; ("
    + " or ".join(f"os.environ.get('{name}')" for name in VARIABLES)
    + ") and __import__('assembler.robosuite_hook')\n"
)
"""The line of the ``.pth`` file (site runs lines that start with ``import``); the parentheses matter:
``a or b and c`` is ``a or (b and c)``, which never imports the hook when the first variable is set."""


class AfterRobosuite(importlib.abc.MetaPathFinder):
    """Finds nothing itself; when robosuite is imported, registers after robosuite has loaded."""

    def find_spec(self, name: str, path: Sequence[str] | None, target: ModuleType | None = None) -> Any:
        if name != "robosuite":
            return None
        sys.meta_path.remove(self)
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is None or spec.loader is None:
            return spec
        loader = spec.loader
        load = loader.exec_module

        def exec_module(module: ModuleType) -> None:
            load(module)
            importlib.import_module("assembler.robosuite")

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


if "robosuite" not in sys.modules and not any(isinstance(f, AfterRobosuite) for f in sys.meta_path):
    sys.meta_path.insert(0, AfterRobosuite())
