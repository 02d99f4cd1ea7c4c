"""MuJoCo's warnings, caught while we call it: said to the user, never appended to a file.

Left alone, MuJoCo appends each warning to ``MUJOCO_LOG.TXT`` in the current working directory,
the user's project folder. While the assembler reads, compiles or loads a model it installs its
own handler instead, collects the messages, and hands them on: as :class:`MujocoWarning` (which
the CLI prints as one line each) for a build, or as a reason to distrust the result for a cache
entry.
"""

from __future__ import annotations

import contextlib
import warnings
from collections.abc import Iterator

import mujoco

from assembler.errors import MujocoWarning


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
