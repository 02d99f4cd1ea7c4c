"""A cache lookup of the compile service without the compiler: the model stored under a key, the
store the environment points at, an assembly's key, and the counts of hits and misses.

Split from :mod:`assembler.compiler.service` so that a request answered from its record
(:mod:`assembler.answers.records`, ``assemble(name).get_model()`` in a new process) imports neither
the compile path (the mesh swap and store, MJCF emission, bundles) nor anything it reads: every
module imported is time the cached answer pays against MuJoCo's own load of the ``.mjb``.
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco

from assembler.cache.build_inputs import BuildInputs
from assembler.cache.key import cache_key
from assembler.cache.memory import RecentModels
from assembler.cache.store import ModelStore
from assembler.files.cache_location import cache_dir, cache_disabled, max_bytes


@dataclass
class LookupCounts:
    """What compiles in this process did, for tests and the benchmark."""

    hits: int = 0
    """Answered from the cache."""

    misses: int = 0
    """Not in the cache: compiled (or patched), then stored."""

    patched: int = 0
    """Of the misses, those answered by patching the cached model of the robot without its overrides
    (:mod:`assembler.patch.robot_variant`) rather than compiled."""

    bypassed: int = 0
    """Compiled without looking: cache disabled, or a part the key cannot describe."""


counts = LookupCounts()

recent = RecentModels()
"""Models loaded from the cache in this process, copied on a repeated load."""


def default_store() -> ModelStore:
    """The store the environment points at (``ASSEMBLER_CACHE_DIR``, ``ASSEMBLER_CACHE_MAX_BYTES``;
    the bound is the whole cache folder's, :mod:`assembler.cache.folder`)."""
    return ModelStore(cache_dir(), max_bytes())


def load_entry(key: str, counted: bool = True) -> mujoco.MjModel | None:
    """The model stored under ``key`` if its files are unchanged (a hit, counted unless ``counted``
    is False), else None; a model loaded before in this process is copied from memory
    (:mod:`assembler.cache.memory`). The model returned is the caller's own to change."""
    models = default_store()
    place = (str(models.directory), key)
    model = recent.get(place)
    if model is None:
        models.wait_for(key)
        found = models.load(key)
        model = recent.offer(place, *found) if found is not None else None
    if model is not None and counted:
        counts.hits += 1
    return model


def entry_key(inputs: BuildInputs, cache: bool = True) -> str | None:
    """The cache entry that holds the model ``inputs`` describe, or None when the cache is not used:
    ``cache=False`` (``--no-cache``), ``ASSEMBLER_NO_CACHE``, or a hand-written part. Computed once
    per request by the caller and passed on, so no key is hashed twice."""
    return cache_key(inputs) if cache and not cache_disabled() else None
