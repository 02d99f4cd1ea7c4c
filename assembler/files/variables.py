"""Environment variables changed for a block and put back after it.

Several settings are environment variables rather than arguments (the cache switched off, the
folders specs may read, ROS package folders) so that the worker processes a command starts inherit
them; a command or a test that changes one for a while uses :func:`restored_after`.
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterator


@contextlib.contextmanager
def restored_after(name: str) -> Iterator[None]:
    """The block may change the variable ``name``; afterwards it is as before (unset if it was)."""
    before = os.environ.get(name)
    try:
        yield
    finally:
        if before is None:
            os.environ.pop(name, None)
        else:
            os.environ[name] = before
