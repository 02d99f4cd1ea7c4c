"""Arm actuators as robosuite's controllers expect them.

robosuite's arm controllers (OSC, joint torque, IK) write torques into ``ctrl``. A robot whose MJCF
drives its arms with position servos says what robosuite should do with them
(``robosuite.actuation``): ``torque`` turns each servo into a motor whose control range is the
servo's force range, and each DC motor a ``motors:`` entry drives in volts into a motor whose ctrl is
the joint torque within the motor's torque limit; ``as_is`` keeps them. Never guessed: a robot with
such actuators on its arms that says neither is an error that names them.
"""

from __future__ import annotations

from collections.abc import Collection, Mapping

import mujoco

from assembler.mjcf.actuators import find_actuator
from assembler.robosuite.conventions import is_servo, limits_force


def is_position_servo(actuator: mujoco.MjsActuator) -> bool:
    """An actuator of a spec that is a position servo (:func:`~assembler.robosuite.conventions.is_servo`)."""
    return is_servo(int(actuator.gaintype), int(actuator.biastype), float(actuator.biasprm[1]))


def position_servos(mjspec: mujoco.MjSpec, names: Collection[str]) -> list[mujoco.MjsActuator]:
    """The position servos among the actuators named ``names``, in MJCF order."""
    return [a for a in mjspec.actuators if a.name in names and is_position_servo(a)]


def has_force_range(actuator: mujoco.MjsActuator) -> bool:
    """Whether the servo of a spec says how much force it may use (the motor's range to be); "auto"
    limits it where a range is given, as the compiler's autolimits do."""
    limited = actuator.forcelimited != mujoco.mjtLimited.mjLIMITED_FALSE
    return limits_force(limited, actuator.forcerange)


def motorize(servos: Collection[mujoco.MjsActuator]) -> None:
    """Turn each servo (each with a force range) into a motor whose control range is that range."""
    for actuator in servos:
        low, high = (float(value) for value in actuator.forcerange)
        actuator.set_to_motor()
        actuator.biasprm = [0.0] * len(actuator.biasprm)  # set_to_motor keeps -kp, unused but misleading
        actuator.ctrlrange = [low, high]
        actuator.ctrllimited = mujoco.mjtLimited.mjLIMITED_TRUE
        actuator.forcelimited = mujoco.mjtLimited.mjLIMITED_FALSE


def torque_motors(mjspec: mujoco.MjSpec, limits: Mapping[str, float]) -> None:
    """Turn each actuator named in ``limits`` (a DC motor that takes volts) into the motor ``control:
    torque`` gives its joint: ctrl is the joint torque (gear 1), ctrlrange = forcerange = ±limit."""
    for name, limit in limits.items():
        actuator = find_actuator(mjspec, name)
        assert actuator is not None  # named by the part's own actuator records
        actuator.set_to_motor()  # gain 1, no bias, no dynamics: the back-EMF is the driver's to handle
        # MuJoCo 3.9's set_to_motor leaves the DC motor's other parameters ([R, K, ...]) in place
        actuator.gainprm = [1.0] + [0.0] * (len(actuator.gainprm) - 1)
        actuator.biasprm = [0.0] * len(actuator.biasprm)
        actuator.dynprm = [1.0] + [0.0] * (len(actuator.dynprm) - 1)  # MuJoCo's default
        actuator.gear = [1.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        for attribute in ("ctrl", "force"):
            setattr(actuator, f"{attribute}range", [-limit, limit])
            setattr(actuator, f"{attribute}limited", mujoco.mjtLimited.mjLIMITED_TRUE)
