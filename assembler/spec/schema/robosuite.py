"""How a robot enters robosuite's environments (``import assembler.robosuite``): a robot spec's
``robosuite:`` block. Every field has a default chosen by the robot's arms and base, so a simple
arm driven by motors needs none of them."""

from __future__ import annotations

from typing import Any, Literal

from assembler.spec.schema.common import FiniteFloat, StrictModel
from assembler.spec.schema.parts import Name

RobotType = Literal["FixedBaseRobot", "WheeledRobot", "LeggedRobot"]
"""robosuite's Robot classes (robots.ROBOT_CLASS_MAPPING's values)."""

Actuation = Literal["torque", "as_is"]
"""How the actuators robosuite's controllers drive reach robosuite (which writes torques into ``ctrl``)."""


class RobosuiteOptions(StrictModel):
    """What robosuite needs of a robot beyond its model; null fields take their default."""

    enabled: bool = True
    """Whether ``import assembler.robosuite`` (or ``register`` of its folder) offers the robot to robosuite;
    false for a robot robosuite's controllers cannot drive (say why beside it)."""

    controller: str | dict[str, Any] | None = None
    """The composite controller configuration robosuite builds the robot's controllers from: one of
    robosuite's by name (e.g. BASIC, default_panda), a .json file (relative to this spec), or the
    configuration itself (type, body_parts, ...; joint and site names without the robot's prefix); null:
    robosuite's default_panda for one arm, default_baxter for two, plus robosuite's settings for the base,
    torso, head and legs the robot has actuators for (robosuite's own robots keep robosuite's choice)."""

    robot_type: RobotType | None = None
    """robosuite's Robot class, which decides what gets controllers (FixedBaseRobot: the arms;
    WheeledRobot: also the base, torso and head; LeggedRobot: also the legs); null: WheeledRobot on a mobile
    base, LeggedRobot on a legged base or for a legged morphology, FixedBaseRobot otherwise (the base is
    default_base, else stand_in_base)."""

    actuation: Actuation | None = None
    """torque: each position servo robosuite's controllers drive (the arms'; the torso's and head's on a
    wheeled or legged robot; the legs' on a legged robot) becomes a motor whose ctrlrange is the servo's
    forcerange (each must give one), and each DC motor a motors: entry drives in volts becomes the motor
    control: torque gives its joint (ctrlrange ±(peak or stall torque)·N·η); as_is: keep the actuators as
    the MJCF and the motors: entries make them; null: as_is when none of them is a position servo or takes
    volts, else an error that asks you to choose."""

    init_torso_qpos: list[FiniteFloat] | None = None
    """Torso joint positions robosuite sets at each reset (robosuite's init_torso_qpos), or null."""

    init_base_qpos: list[FiniteFloat] | None = None
    """Base joint positions robosuite sets at each reset (robosuite's init_base_qpos), or null."""

    stand_in_base: Name | None = None
    """The base used in robosuite when the spec's default_base is null (robosuite cannot build a robot
    without one); null: NoActuationBase for humanoids and legged manipulators (robosuite's GR1 stands
    on it, and their robot class reads its center site), NullMount for other robots."""
