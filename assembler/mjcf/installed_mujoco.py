"""The installed MuJoCo as we call it: which version it is, and the warnings it raises while we call it.

**Its version**, for the few places where the MuJoCo versions we support behave differently. The core
supports MuJoCo 3.9.0 (the newest robosuite 1.5.2 runs on) up to the newest release; CI tests both
ends. Each version check names the behaviour it guards and the release that changed it.

**Its warnings**, said to the user, never appended to a file. Left alone, MuJoCo appends each warning
to ``MUJOCO_LOG.TXT`` in the current working directory, the user's project folder. While the
assembler reads, compiles or loads a model it installs its own handler instead, collects the
messages, and hands them on: as :class:`MujocoWarning` (which the CLI prints as one line each) for a
build, or as a reason to distrust the result for a cache entry.
"""

from __future__ import annotations

import contextlib
import warnings
from collections.abc import Iterator

import mujoco

from assembler.errors import MujocoWarning


def parse_version(version: str) -> tuple[int, int]:
    """``"3.16.0"`` -> ``(3, 16)``: major and minor, which is all our checks need."""
    major, minor = (int(part) for part in version.split(".")[:2])
    return major, minor


def mujoco_at_least(major: int, minor: int, version: str = mujoco.__version__) -> bool:
    """True when ``version`` (default: the installed MuJoCo's) is ``major.minor`` or newer."""
    return parse_version(version) >= (major, minor)


@contextlib.contextmanager
def collected() -> Iterator[list[str]]:
    """Collect MuJoCo's warnings raised in the block (in order) instead of MuJoCo's log file."""
    messages: list[str] = []
    previous = mujoco.get_mju_user_warning()
    mujoco.set_mju_user_warning(messages.append)
    try:
        yield messages
    finally:
        mujoco.set_mju_user_warning(previous)


@contextlib.contextmanager
def warned(what: str) -> Iterator[list[str]]:
    """MuJoCo's warnings in the block become :class:`MujocoWarning`s naming ``what``, once each; but
    those starting with a text the block adds to the list it is given (a warning the caller says
    in its own words, with the file's line)."""
    said: list[str] = []
    with collected() as messages:
        yield said
    for message in dict.fromkeys(" ".join(message.split()) for message in messages):
        if message.startswith(tuple(said)) and said:
            continue
        warnings.warn(f"{what}: MuJoCo warns: {message}", MujocoWarning, stacklevel=3)
