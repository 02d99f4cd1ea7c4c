"""Arm actuators as robosuite's controllers expect them.

robosuite's arm controllers (OSC, joint torque, IK) write torques into ``ctrl``. A robot whose MJCF
drives its arms with position servos says what robosuite should do with them
(``robosuite.arm_actuation``): ``torque`` turns each servo into a motor whose control range is the
servo's force range; ``as_is`` keeps them. Never guessed: a robot with arm servos that says neither
is an error that names them.
"""

from __future__ import annotations

from collections.abc import Collection

import mujoco

AFFINE = mujoco.mjtBias.mjBIAS_AFFINE
FIXED = mujoco.mjtGain.mjGAIN_FIXED


def is_position_servo(actuator: mujoco.MjsActuator) -> bool:
    """A servo towards a position target: fixed gain, bias -kp * length (MuJoCo's <position>)."""
    return bool(actuator.gaintype == FIXED and actuator.biastype == AFFINE and actuator.biasprm[1] < 0)


def position_servos(mjspec: mujoco.MjSpec, names: Collection[str]) -> list[mujoco.MjsActuator]:
    """The position servos among the actuators named ``names``, in MJCF order."""
    return [a for a in mjspec.actuators if a.name in names and is_position_servo(a)]


def has_force_range(actuator: mujoco.MjsActuator) -> bool:
    """Whether the servo says how much force it may use (the motor's range to be)."""
    low, high = (float(value) for value in actuator.forcerange)
    return actuator.forcelimited != mujoco.mjtLimited.mjLIMITED_FALSE and low < high


def motorize(servos: Collection[mujoco.MjsActuator]) -> None:
    """Turn each servo (each with a force range) into a motor whose control range is that range."""
    for actuator in servos:
        low, high = (float(value) for value in actuator.forcerange)
        actuator.set_to_motor()
        actuator.biasprm = [0.0] * len(actuator.biasprm)  # set_to_motor keeps -kp, unused but misleading
        actuator.ctrlrange = [low, high]
        actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE
