"""Our robots as mjlab entities: ``entity_cfg(robot)`` gives an ``mjlab.entity.EntityCfg``.

mjlab (``pip install -e ".[mjlab]"``; it pins MuJoCo ~=3.11) builds its scenes from entities whose
``spec_fn`` returns a ``mujoco.MjSpec``; an assembled robot is one. Importing this package imports
mjlab (and torch), which is why nothing else in assembler imports it.
"""

from __future__ import annotations

from assembler.mjlab.entity import ActuatorChoice, entity_cfg, home_joint_positions, mapped_actuators

__all__ = ["ActuatorChoice", "entity_cfg", "home_joint_positions", "mapped_actuators"]
