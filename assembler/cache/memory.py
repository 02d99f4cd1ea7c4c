"""Models asked for more than once in this process, kept in memory, so a repeated load costs a
model copy rather than reading and unpacking the binary model again.

The first load of an entry in a process hands over the model it read, without copying it: a warm
load in a new process stays as cheap as MuJoCo's own load of the file. A second request for the
same entry suggests a loop (an experiment rebuilding its robot each episode), so that load keeps
the model it read and returns a copy, and later requests only copy. The entry's files are still
checked on every request, exactly as for an entry on disk.
"""

from __future__ import annotations

import copy
from collections import OrderedDict
from dataclasses import dataclass

import mujoco

from assembler.cache.dependencies import Dependency, verify

MEMORY_BYTES = 512 * 1024**2
"""At most this much compiled model is kept (a Panda with its gripper is 44 MB)."""

Place = tuple[str, str]
"""(cache folder, key): an entry of one cache, as a test or a user may switch folders."""


@dataclass
class _Kept:
    model: mujoco.MjModel
    dependencies: tuple[Dependency, ...]
    size: int


class RecentModels:
    """Compiled models kept for repeated loads, least recently used dropped first."""

    def __init__(self, max_bytes: int = MEMORY_BYTES) -> None:
        self.max_bytes = max_bytes
        self._kept: OrderedDict[Place, _Kept] = OrderedDict()
        self._seen: set[Place] = set()

    def get(self, place: Place) -> mujoco.MjModel | None:
        """A copy of the kept model, if there is one and its files are unchanged."""
        kept = self._kept.get(place)
        if kept is None:
            return None
        current = verify(kept.dependencies)
        if current is None:
            del self._kept[place]
            return None
        kept.dependencies = tuple(current)
        self._kept.move_to_end(place)
        return copy.copy(kept.model)

    def offer(
        self, place: Place, model: mujoco.MjModel, dependencies: tuple[Dependency, ...]
    ) -> mujoco.MjModel:
        """The model to hand out for one just read from disk: itself the first time, a copy (the
        original kept) when the entry was asked for before."""
        size = mujoco.mj_sizeModel(model)
        if place not in self._seen or size > self.max_bytes:
            self._seen.add(place)
            return model
        self._kept[place] = _Kept(model, dependencies, size)
        while sum(kept.size for kept in self._kept.values()) > self.max_bytes:
            self._kept.popitem(last=False)
        return copy.copy(model)

    def forget(self, folder: str) -> None:
        """Drop every model of one cache folder (``assembler cache clear``)."""
        for place in [place for place in self._kept if place[0] == folder]:
            del self._kept[place]
        self._seen = {place for place in self._seen if place[0] != folder}
