"""Which MuJoCo is installed, for the few places where MuJoCo versions we support behave differently.

The core supports MuJoCo 3.9.0 (the newest robosuite 1.5.2 runs on) up to the newest release; CI
tests both ends. Each version check names the behaviour it guards and the release that changed it.
"""

from __future__ import annotations

import mujoco


def parse_version(version: str) -> tuple[int, int]:
    """``"3.16.0"`` -> ``(3, 16)``: major and minor, which is all our checks need."""
    major, minor = (int(part) for part in version.split(".")[:2])
    return major, minor


def mujoco_at_least(major: int, minor: int, version: str = mujoco.__version__) -> bool:
    """True when ``version`` (default: the installed MuJoCo's) is ``major.minor`` or newer."""
    return parse_version(version) >= (major, minor)
