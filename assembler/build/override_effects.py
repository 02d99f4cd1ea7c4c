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
from assembler.spec.documents import Override
from assembler.models import RobotModel


def model_digest(model: mujoco.MjModel) -> str:
    """A digest of everything in a compiled model (MuJoCo's own binary form of it)."""
    buffer = np.empty(mujoco.mj_sizeModel(model), dtype=np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer_digest(buffer)


def overrides_without_effect(
    build: Callable[[Sequence[Override]], RobotModel], overrides: Sequence[Override], cache: bool = True
) -> list[Override]:
    """The overrides whose removal leaves the compiled model the same; ``build`` assembles the robot
    with the overrides it is given."""
    if not overrides:
        return []
    full = model_digest(build(overrides).get_model(cache=cache))
    idle: list[Override] = []
    for override in overrides:
        others = [other for other in overrides if other is not override]
        if model_digest(build(others).get_model(cache=cache, store=False)) == full:
            idle.append(override)
    return idle
