"""RA701, RA704: a robot that robosuite's environments would refuse or fail on.

RA701 is an error for a robot robosuite is offered (``robosuite.enabled``, the default): the bridge
refuses it at ``robosuite.make``.

robosuite's arm controllers write torques into ``ctrl``, so the bridge needs to be told what to do
with position servos there (``robosuite.actuation``), and turning a servo into a motor takes its
force range. Its composite controller reads each arm's origin from a site ``{arm}_center`` at
every step. The robot builds and simulates without any of this; only robosuite minds, so a robot
that does not declare robosuite use gets warnings, and one that does (``actuation: torque``) an
error. These checks read our model only: robosuite need not be installed.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.models import ManipulatorModel
from assembler.robosuite.conventions import (
    ACTUATION,
    arm_center_site,
    driven_actuators,
    has_force_range,
    is_bridge_servo,
)
from assembler.spec.fieldpath import FieldPath
from assembler.tools.lint.finding import Finding
from assembler.tools.lint.target import ACTUATOR_TAGS, LintTarget

ACTUATOR = mujoco.mjtObj.mjOBJ_ACTUATOR
ACTUATOR = mujoco.mjtObj.mjOBJ_ACTUATOR


def _robots(target: LintTarget) -> Iterator[ManipulatorModel]:
    """The robot of a robot target, when it has arms (robosuite takes no other)."""
    robot = target.parts[0] if target.parts else None
    if isinstance(robot, ManipulatorModel):
        yield robot


def servos_robosuite_cannot_drive(target: LintTarget) -> Iterator[Finding]:
    """RA701: robosuite's controllers would drive position servos, and the spec sets no
    ``robosuite.actuation`` (warning), or sets ``torque`` for a servo without forcerange (error)."""
    model = target.model
    for robot in _robots(target):
        ids = {name: mujoco.mj_name2id(model, ACTUATOR, name) for name in driven_actuators(robot)}
        servos = [name for name, index in ids.items() if index >= 0 and is_bridge_servo(model, index)]
        choice = robot.spec.robosuite.actuation
        if servos and choice is None:
            yield Finding(
                code="RA701",
                severity="error" if robot.spec.robosuite.enabled else "warning",
                subject=type(robot).__name__,
                why=(
                    f"the actuators robosuite's controllers drive ({', '.join(servos)}) are position servos, "
                    "but those controllers write torques into ctrl and robosuite.actuation is not set: "
                    "robosuite refuses the robot"
                ),
                fix=(
                    "set robosuite.actuation to torque (each servo becomes a motor whose ctrlrange is its "
                    "forcerange) or to as_is (keep the servos)"
                ),
                location=target.spec_location(robot, ACTUATION),
            )
        if choice != "torque":
            continue
        for name in servos:
            if has_force_range(model, ids[name]):
                continue
            yield Finding(
                code="RA701",
                severity="error",
                subject=name,
                why=(
                    "robosuite.actuation is torque, but this position servo has no forcerange to become "
                    "its motor's ctrlrange: robosuite refuses the robot"
                ),
                fix=(
                    "give the actuator a forcerange (its torque or force limits), "
                    "or set robosuite.actuation to as_is"
                ),
                location=target.element_location(ACTUATOR_TAGS, name),
            )


def missing_arm_centers(target: LintTarget) -> Iterator[Finding]:
    """RA704 (info): an arm without the ``{arm}_center`` site robosuite's composite controller reads,
    which ``assembler.robosuite`` then adds for robosuite (and says so)."""
    model = target.model
    for robot in _robots(target):
        for arm in robot.arms:
            site = robot.naming_prefix + arm_center_site(arm)
            if mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_SITE, site) >= 0:
                continue
            yield Finding(
                code="RA704",
                severity="info",
                subject=site,
                why=(
                    f"robosuite's composite controller reads the {arm} arm's origin from site "
                    f"{arm_center_site(arm)} at every step, and the model has none: in robosuite's "
                    "environments it is added on the body the arm's first link hangs from"
                ),
                fix=_center_fix(robot.spec.source_field, arm_center_site(arm), arm),
                location=target.spec_location(robot, FieldPath((robot.spec.source_field,))),
            )


def _center_fix(source_field: str, site: str, arm: str) -> str:
    """Where the site goes: the robot's MJCF, or for a URDF robot (no sites) an MJCF made of it."""
    where = f'add <site name="{site}"/> to the body the {arm} arm starts from (robosuite\'s Panda: link0)'
    if source_field == "urdf":
        return f"{where}, in an MJCF of the robot: a URDF holds no sites"
    return f"{where}, in the robot's MJCF"
