"""The names robosuite's registries hold (its own robots, grippers and bases, and those of packages it
imports, such as robosuite_models), so that ``assembler new`` names a spec none of them has.

robosuite is optional and slow to import (about two seconds), so it is imported here only, through
importlib, and only when it is installed: a spec named like one of its classes would be refused when
it enters robosuite (``assembler.robosuite.register``).
"""

from __future__ import annotations

import importlib
import io
from contextlib import redirect_stderr, redirect_stdout

from assembler.files.paths import package_root

TABLES: tuple[tuple[str, str], ...] = (
    ("robosuite.robots", "REGISTERED_ROBOTS"),
    ("robosuite.models.grippers", "GRIPPER_MAPPING"),
    ("robosuite.models.bases", "BASE_MAPPING"),
)
"""Where robosuite keeps each family's names."""


def robosuite_names() -> set[str]:
    """Every name in robosuite's registries; empty when robosuite is not installed."""
    if package_root("robosuite") is None:
        return set()
    names: set[str] = set()
    with redirect_stdout(io.StringIO()), redirect_stderr(io.StringIO()):  # robosuite's start-up chatter
        for module, table in TABLES:
            names.update(str(name) for name in getattr(importlib.import_module(module), table, {}) if name)
    return names
