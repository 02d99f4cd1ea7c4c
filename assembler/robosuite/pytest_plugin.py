"""robosuite's own test suite against our specs: ``pytest -p assembler.robosuite.pytest_plugin``.

Loaded before any test module is imported, the plugin replaces every robosuite robot, gripper and
base that has a spec of the same name by the class built from that spec, in robosuite's registries
and as module attributes (robosuite's tests import classes both ways). The tests run unmodified.
"""

from __future__ import annotations

from typing import Any

import assembler.robosuite

REPLACED = assembler.robosuite.replace_robosuite()
"""The names replaced, robots, grippers and bases."""


def pytest_report_header(config: Any) -> str:
    """One header line naming what the tests run on."""
    return f"robot-assembler: {len(REPLACED)} of robosuite's robots, grippers and bases are built from specs"
