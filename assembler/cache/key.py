"""The cache key of an assembly: a hash of its build inputs, computed without reading any MJCF
(ccache's "direct mode").

The key covers the :class:`~assembler.cache.build_inputs.BuildInputs` (each part's validated spec,
class, idn, MJCF file and API joint edits; the robot's placement), the assembler's own code and
MuJoCo's version. The files the compile reads are not in the key: the entry lists them (see
:mod:`assembler.cache.dependencies`) and a lookup checks them.
"""

from __future__ import annotations

import dataclasses
import functools
import hashlib
import json
import os
import sys
from pathlib import Path

import mujoco

from assembler.cache.build_inputs import BuildInputs
from assembler.version import __version__

FORMAT = 4
"""Version of the entry layout and of the key's contents; bump it when either changes."""

_PACKAGE = Path(__file__).resolve().parent.parent


@functools.lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """The assembler's version and a digest of its Python sources' names, sizes and times.

    The version alone is not enough: an editable install changes the code without changing the
    version, and a stale model after a code change would be a silent wrong answer. Stat rather
    than content keeps this under a millisecond; an edit or a new install changes the times.
    """
    found = []
    for folder, _, names in os.walk(_PACKAGE):  # os.walk, not Path.rglob: a third of the time
        inside = os.path.relpath(folder, _PACKAGE)
        for name in names:
            if name.endswith(".py"):
                stat = os.stat(os.path.join(folder, name))
                found.append((os.path.normpath(os.path.join(inside, name)), stat.st_size, stat.st_mtime_ns))
    digest = hashlib.blake2b(digest_size=16)
    for relative, size, mtime_ns in sorted(found):
        digest.update(f"{relative}:{size}:{mtime_ns};".encode())
    return f"{__version__}+{digest.hexdigest()}"


PACKAGE_VARIABLES = ("ROS_PACKAGE_PATH", "AMENT_PREFIX_PATH")
"""The environment variables that decide where ``package://NAME`` leads (:mod:`assembler.files.paths`)."""

MENAGERIE_VARIABLES = ("MENAGERIE_ROOT", "MENAGERIE_CACHE_DIR")
"""The variables that decide where ``menagerie://NAME`` leads (:mod:`assembler.files.menagerie`)."""


def resolution_environment() -> dict[str, object]:
    """What decides which files a build reads besides its spec: the package and Menagerie variables, the
    Python environment and its import path (an installed package is a package root). Part of every key,
    so a switched ``ROS_PACKAGE_PATH`` is a miss, never the other copy's model. The import path's
    first entry is left out: it is the script's folder or the working folder, which differ between
    ``assembler`` and ``python -c`` for one environment; relative names are resolved before keying."""
    return {
        **{name: os.environ.get(name, "") for name in (*PACKAGE_VARIABLES, *MENAGERIE_VARIABLES)},
        "prefix": sys.prefix,
        "path": [os.path.abspath(entry) for entry in sys.path[1:]],
    }


def cache_key(inputs: BuildInputs) -> str | None:
    """The key of the assembly ``inputs`` describe, or None when it cannot be cached (a part is
    hand-written Python)."""
    if not inputs.cacheable:
        return None
    material = {
        "format": FORMAT,
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "environment": resolution_environment(),
        "inputs": dataclasses.asdict(inputs),
    }
    text = json.dumps(material, sort_keys=True, separators=(",", ":"))
    return hashlib.blake2b(text.encode(), digest_size=20).hexdigest()
