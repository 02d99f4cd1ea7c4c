"""Which ``--set`` overrides change nothing in the compiled model, so a build can say so.

An override that changes nothing is almost always a mistake a reviewer would want flagged:
``joint_defaults.damping`` on a robot whose ``joints:`` set damping on every joint, say. Each
override is tested by building without it (from the cache when the plain robot is there) and
comparing the two compiled models byte for byte.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

import mujoco
import numpy as np

from assembler.cache.file_state import buffer_digest
from assembler.models import RobotModel
from assembler.spec.documents import Override


def model_digest(model: mujoco.MjModel) -> str:
    """A digest of everything in a compiled model (MuJoCo's own binary form of it)."""
    buffer = np.empty(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer_digest(buffer)


def superseded(overrides: Sequence[Override]) -> list[bool]:
    """For each override, whether a later one sets the same field or a field containing it: its value
    is replaced, so it changes nothing (found in one pass, without building anything)."""
    later: set[tuple[str | int, ...]] = set()
    found = []
    for override in reversed(overrides):
        path = tuple(override.path)
        found.append(any(path[:depth] in later for depth in range(len(path) + 1)))
        later.add(path)
    return found[::-1]


def overrides_without_effect(
    build: Callable[[Sequence[Override]], RobotModel], overrides: Sequence[Override], cache: bool = True
) -> list[Override]:
    """The overrides whose removal leaves the compiled model the same; ``build`` assembles the robot
    with the overrides it is given.

    An override a later one replaces is idle without a build; each other one is removed in turn
    from the overrides that count (one build per field set, not per flag: ``--set`` given 1,280
    times for one field costs two builds, not 1,280 builds of 1,280 overrides each)."""
    if not overrides:
        return []
    replaced = superseded(overrides)
    counting = [index for index, gone in enumerate(replaced) if not gone]
    full = model_digest(build(overrides).get_model(cache=cache))
    idle = {index for index, gone in enumerate(replaced) if gone}
    for index in counting:
        others = [overrides[other] for other in counting if other != index]
        if model_digest(build(others).get_model(cache=cache, store=False)) == full:
            idle.add(index)
    return [overrides[index] for index in sorted(idle)]
