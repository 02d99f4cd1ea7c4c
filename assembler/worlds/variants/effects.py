"""Which ``--set`` overrides change nothing in the compiled model, so a build can say so.

An override that changes nothing is almost always a mistake a reviewer would want flagged:
``joint_defaults.damping`` on a robot whose ``joints:`` set damping on every joint, say. Each
override is tested by building without it (from the cache when the plain robot is there) and
comparing the two compiled models field by field. Not byte for byte: one of the two may be a variant
patched onto the cached robot (:mod:`assembler.patch.robot_variant`) and the other compiled, and those agree
to 1e-10, not to the last bit.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.models import RobotModel
from assembler.spec.documents import Override

RELATIVE = 1e-9
"""How close two numbers of two models must be to be the same (a patch agrees with a compile to 1e-10)."""


def _arrays(model: mujoco.MjModel) -> dict[str, NDArray[Any]]:
    return {
        name: value
        for name in dir(model)
        if not name.startswith("_") and isinstance(value := getattr(model, name), np.ndarray)
    }


def same_model(first: mujoco.MjModel, second: mujoco.MjModel) -> bool:
    """True when every array of the two compiled models is the same: integers (counts, addresses,
    names) equal, numbers equal to :data:`RELATIVE` (or 1e-12 absolute)."""
    if mujoco.mj_sizeModel(first) != mujoco.mj_sizeModel(second):
        return False
    mine, theirs = _arrays(first), _arrays(second)
    if mine.keys() != theirs.keys():
        return False
    for name, value in mine.items():
        other = theirs[name]
        if value.shape != other.shape:
            return False
        if np.issubdtype(value.dtype, np.floating):
            if not np.allclose(value, other, rtol=RELATIVE, atol=1e-12, equal_nan=True):
                return False
        elif not np.array_equal(value, other):
            return False
    return True


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
    full = build(overrides).get_model(cache=cache)
    idle = {index for index, gone in enumerate(replaced) if gone}
    for index in counting:
        others = [overrides[other] for other in counting if other != index]
        if same_model(build(others).get_model(cache=cache, store=False), full):
            idle.add(index)
    return [overrides[index] for index in sorted(idle)]
