"""Our robots as mjlab entities: ``entity_cfg(robot)`` gives an ``mjlab.entity.EntityCfg``.

mjlab (``pip install -e ".[mjlab]"``; it pins MuJoCo ~=3.11) builds its scenes from entities whose
``spec_fn`` returns a ``mujoco.MjSpec``; an assembled robot is one. Importing this package imports
mjlab (and torch), which is why nothing else in assembler imports it. ``use_robot(cfg, robot)`` puts a
spec robot into mjlab's own velocity task (``make_velocity_env_cfg()``), as the spec's ``mjlab:`` says.
"""

from __future__ import annotations

from assembler.mjlab.entity import (
    ActuatorChoice,
    entity_cfg,
    feet_sensor,
    for_mjlab,
    home_joint_positions,
    mapped_actuators,
)
from assembler.mjlab.velocity import use_robot

__all__ = [
    "ActuatorChoice",
    "entity_cfg",
    "feet_sensor",
    "for_mjlab",
    "home_joint_positions",
    "mapped_actuators",
    "use_robot",
]
