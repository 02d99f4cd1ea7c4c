"""The compiled-model cache: a robot whose inputs have not changed loads MuJoCo's binary model
from disk instead of compiling its meshes again.

A lookup hashes what defines the assembly (:mod:`assembler.cache.key`), finds the entry
(:mod:`assembler.cache.store`) and checks the files it was compiled from
(:mod:`assembler.cache.dependencies`); nothing is assembled on a hit. A robot loaded again and
again in one process is copied from memory (:mod:`assembler.cache.memory`). ``--no-cache``,
``ASSEMBLER_NO_CACHE=1`` or ``robot.use_cache = False`` turn it off; :mod:`assembler.cache.settings`
has the other knobs.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import TYPE_CHECKING

import mujoco

from assembler.cache.dependencies import Recorder, part_files, source_files
from assembler.cache.key import robot_key
from assembler.cache.memory import RecentModels
from assembler.cache.settings import cache_dir, cache_disabled, max_bytes
from assembler.cache.store import CacheInfo, ModelStore, wait_for_writes

if TYPE_CHECKING:
    from assembler.models.robot_model import RobotModel

__all__ = [
    "CacheInfo",
    "LookupCounts",
    "ModelStore",
    "cache_dir",
    "cache_disabled",
    "clear",
    "counts",
    "default_store",
    "load_or_compile",
    "wait_for_writes",
]


@dataclass
class LookupCounts:
    """What ``get_model()`` calls in this process did, for tests and the benchmark."""

    hits: int = 0
    """Answered from the cache."""

    misses: int = 0
    """Compiled, then stored."""

    bypassed: int = 0
    """Compiled without looking: cache disabled, or a part the key cannot describe."""


counts = LookupCounts()

_recent = RecentModels()


def default_store() -> ModelStore:
    """The store the environment points at (``ASSEMBLER_CACHE_DIR``, ``ASSEMBLER_CACHE_MAX_BYTES``)."""
    return ModelStore(cache_dir(), max_bytes())


def clear(store: ModelStore) -> CacheInfo:
    """Empty ``store``, and forget the models this process kept from it; returns what was there."""
    _recent.forget(str(store.directory))
    return store.clear()


def load_or_compile(robot: RobotModel, compile_model: Callable[[], mujoco.MjModel]) -> mujoco.MjModel:
    """``robot``'s model from the cache, or ``compile_model()``'s result, stored for next time."""
    key = None if cache_disabled() else robot_key(robot)
    if key is None:
        counts.bypassed += 1
        return compile_model()
    store = default_store()
    place = (str(store.directory), key)
    model = _recent.get(place)
    if model is not None:
        counts.hits += 1
        return model
    found = store.load(key)
    if found is not None:
        counts.hits += 1
        return _recent.offer(place, *found)
    counts.misses += 1
    parts = [robot, *robot.models]
    read_earlier = {path: stat for part in parts for path, stat in source_files(part).items()}
    recorder = Recorder((file for part in parts for file in part_files(part)), read_earlier)
    model = compile_model()
    store.save(key, model, recorder, " + ".join(part.name for part in parts))
    return model
