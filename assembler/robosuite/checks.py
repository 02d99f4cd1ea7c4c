"""robosuite's lint checks (RA701-RA708): what ``assembler.robosuite`` would refuse at ``robosuite.make``
or robosuite's environments would fail on, found before. They read our model and ask the bridge's own
functions where those need no robosuite, so the two cannot disagree; robosuite need not be installed
(tests/tools/test_lint_bridge.py checks that every refusal in assembler/robosuite has its check).

- RA701, RA704, robots: robosuite's arm controllers write torques into ``ctrl``, so the bridge needs
  to be told what to do with position servos there (``robosuite.actuation``; an error for a robot
  robosuite is offered, ``robosuite.enabled``, the default, a warning otherwise) and with DC motors a
  ``motors:`` entry drives in volts (the same), and turning a servo into a motor takes its force
  range. The composite controller reads each arm's origin from a site ``{arm}_center`` at every step.
- RA702-RA703, grippers: robosuite finds a gripper's frame by a body named ``eef`` and its grip
  point by the sites ``grip_site`` and ``grip_site_cylinder``; where a gripper lacks them, the bridge
  adds them at the spec's ``eef_body`` (RA702, info). robosuite refuses a gripper with actuators that
  declares no ``actions:`` (RA703).
- RA705-RA708, the rest of the bridge's refusals: a joint robosuite's controllers would drive with
  no actuator (RA705), a ``base_xpos_offset`` robosuite cannot read (RA706), euler angles in another
  sequence than robosuite's world reads (RA707), a ``robosuite.controller`` the bridge cannot build
  (RA708).
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Iterator

import mujoco

from assembler.checks.finding import Finding
from assembler.checks.target import ACTUATOR_TAGS, LintTarget
from assembler.errors import SpecError
from assembler.models import GripperModel, ManipulatorModel
from assembler.robosuite.conventions import (
    ACTUATION,
    CONTROLLER,
    GRIP_FRAMES,
    arm_center_site,
    driven_actuators,
    grip_sensors,
    has_force_range,
    is_bridge_servo,
    offered,
)
from assembler.robosuite.parts import driven_voltage_motors, undriven_joints, why_undriven
from assembler.spec.expressions import ExpressionError
from assembler.spec.fieldpath import FieldPath

ACTUATOR = mujoco.mjtObj.mjOBJ_ACTUATOR
ACTUATOR = mujoco.mjtObj.mjOBJ_ACTUATOR


def _robots(target: LintTarget) -> Iterator[ManipulatorModel]:
    """The robot of a robot target, when it has arms (robosuite takes no other)."""
    robot = target.parts[0] if target.parts else None
    if isinstance(robot, ManipulatorModel):
        yield robot


def servos_robosuite_cannot_drive(target: LintTarget) -> Iterator[Finding]:
    """RA701: robosuite's controllers would drive position servos or DC motors taking volts, and the spec
    sets no ``robosuite.actuation`` (warning), or sets ``torque`` for a servo without forcerange (error)."""
    model = target.model
    for robot in _robots(target):
        ids = {name: mujoco.mj_name2id(model, ACTUATOR, name) for name in driven_actuators(robot)}
        servos = [name for name, index in ids.items() if index >= 0 and is_bridge_servo(model, index)]
        choice = robot.spec.robosuite.actuation
        undecided = (
            (
                servos,
                "are position servos",
                "each servo becomes a motor whose ctrlrange is its forcerange",
                "keep the servos",
            ),
            (
                [robot.naming_prefix + name for name in driven_voltage_motors(robot)],
                "take volts (motors: control: voltage)",
                "each becomes a motor within its motor's torque limit, ±(peak or stall torque)·N·η",
                "keep volts",
            ),
        )
        for names, what, torque, kept in undecided if choice is None else ():
            if not names:
                continue
            yield Finding(
                code="RA701",
                severity="error" if robot.spec.robosuite.enabled else "warning",
                subject=type(robot).__name__,
                why=(
                    f"the actuators robosuite's controllers drive ({', '.join(names)}) {what}, but those "
                    "controllers write torques into ctrl and robosuite.actuation is not set: robosuite "
                    "refuses the robot"
                ),
                fix=f"set robosuite.actuation to torque ({torque}) or to as_is ({kept})",
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


def _grippers(target: LintTarget) -> Iterator[GripperModel]:
    for part in target.parts:
        if isinstance(part, GripperModel):
            yield part


def grip_frames_added_for_robosuite(target: LintTarget) -> Iterator[Finding]:
    """RA702 (info): a gripper lacks robosuite's ``eef`` body or grip sites, which robosuite then gets
    at the spec's ``eef_body``."""
    for part in _grippers(target):
        looked_up = [*GRIP_FRAMES, *grip_sensors(part.spec.important_sensors)]
        missing = [
            f"{kind.name.removeprefix('mjOBJ_').lower()} '{name}'"
            for kind, name in looked_up
            if mujoco.mj_name2id(target.model, kind, part.naming_prefix + name) < 0
        ]
        if not missing:
            continue
        eef_body = part.spec.eef_body
        yield Finding(
            code="RA702",
            severity="info",
            subject=type(part).__name__,
            why=(
                "robosuite looks a gripper up by body 'eef', sites 'grip_site' and 'grip_site_cylinder' and "
                f"its force and torque sensors; this one lacks {', '.join(missing)}, which robosuite gets "
                f"at body '{eef_body}' (eef_body; the sensors at the gripper's root)"
            ),
            fix=(
                f"nothing, if body '{eef_body}' is the grip point; else add them to the MJCF where the "
                "fingers close"
            ),
            location=target.spec_location(part, FieldPath(("eef_body",))),
        )


def gripper_without_actions(target: LintTarget) -> Iterator[Finding]:
    """RA703 (error): a gripper has actuators but no ``actions:`` saying how a policy drives them
    (the bridge refuses it at ``robosuite.make``)."""
    for part in _grippers(target):
        if part.spec.actions is not None or not part.actuators:
            continue
        names = ", ".join(name[len(part.naming_prefix) :] for name in part.actuators)
        yield Finding(
            code="RA703",
            severity="error",
            subject=type(part).__name__,
            why=(
                f"the gripper has actuators ({names}) but no actions: block saying how a policy's actions "
                "drive them: robosuite refuses it"
            ),
            fix=(
                "add actions: with one entry per action dimension, naming the actuators it drives and "
                "their direction (docs/robosuite.md, Gripper actions)"
            ),
            location=target.spec_location(part, FieldPath(("actions",))),
        )


def _offered(target: LintTarget) -> Iterator[ManipulatorModel]:
    """The target's robot when robosuite is offered it: the bridge's own rule (robosuite.enabled, and
    arms: a legged robot never enters robosuite), so lint and the bridge cannot disagree."""
    robot = target.parts[0] if target.parts else None
    if isinstance(robot, ManipulatorModel) and offered(type(robot)):
        yield robot


def undriven_controlled_joints(target: LintTarget) -> Iterator[Finding]:
    """RA705 (error): a joint of a group robosuite's controllers drive has no actuator."""
    for robot in _offered(target):
        mjspec = robot.part_mjspec()
        undriven = undriven_joints(robot, mjspec)
        if not undriven:
            continue
        yield Finding(
            code="RA705",
            severity="error",
            subject=type(robot).__name__,
            why=(
                "robosuite's controllers drive each joint of the groups they control with one actuator, "
                f"but {', '.join(undriven)} {'has' if len(undriven) == 1 else 'have'} none "
                f"({why_undriven(undriven, mjspec)}): robosuite refuses the robot"
            ),
            fix=(
                "declare an actuator for each (actuators:), leave the joint out of the arm lists of "
                "joint_groups, or set robosuite.enabled: false"
            ),
            location=target.spec_location(robot, FieldPath(("joint_groups",))),
        )


def unreadable_base_offsets(target: LintTarget) -> Iterator[Finding]:
    """RA706 (error): a base_xpos_offset other than table's uses a variable, which robosuite cannot read."""
    for robot in _offered(target):
        for arena in robot.spec.base_xpos_offset:
            if arena == "table":
                continue
            try:
                robot.spec.resolve_base_xpos_offset(arena)
            except ExpressionError:
                yield Finding(
                    code="RA706",
                    severity="error",
                    subject=type(robot).__name__,
                    why=(
                        f"robosuite reads base_xpos_offset.{arena} as three numbers "
                        "(only table's may use variables)"
                    ),
                    fix=f"write base_xpos_offset.{arena} as three numbers",
                    location=target.spec_location(robot, FieldPath(("base_xpos_offset", arena))),
                )


def foreign_euler_sequences(target: LintTarget) -> Iterator[Finding]:
    """RA707 (error): a part's file reads euler angles in another sequence than xyz."""
    if not any(True for _ in _offered(target)) and not target.hangs_on_moving_body:
        return
    for part in target.parts:
        raw = part.prepared_mjspec.compiler.eulerseq
        sequence = "".join(chr(c) if isinstance(c, int) else str(c) for c in raw)
        if sequence.lower() == "xyz":
            continue
        yield Finding(
            code="RA707",
            severity="error",
            subject=type(part).__name__,
            why=(
                f"the model file's compiler has eulerseq '{sequence}', but robosuite's world reads xyz "
                "euler angles"
            ),
            fix="write the file's orientations as quaternions, or in the xyz sequence",
            location=target.spec_location(part, FieldPath((part.spec.source_field,))),
        )


def unusable_controllers(target: LintTarget) -> Iterator[Finding]:
    """RA708 (error): ``robosuite.controller`` names no configuration the bridge can build; checked
    with the bridge's own reader, which needs robosuite's configuration files (info when absent)."""
    for robot in _offered(target):
        if robot.spec.robosuite.controller is None:
            continue
        location = target.spec_location(robot, CONTROLLER)
        if importlib.util.find_spec("robosuite") is None:
            yield Finding(
                code="RA708",
                severity="info",
                subject=type(robot).__name__,
                why=(
                    "robosuite.controller is not checked: robosuite, whose configurations it names, "
                    "is not installed"
                ),
                fix='install robosuite (pip install "robot-assembler[robosuite]") to check it',
                location=location,
            )
            continue
        # Imported here, through importlib, because the bridge's reader imports robosuite (seconds),
        # which only a spec that names a controller needs.
        controllers = importlib.import_module("assembler.robosuite.controllers")
        try:
            controllers.declared_config(type(robot))
        except SpecError as error:
            yield Finding(
                code="RA708",
                severity="error",
                subject=type(robot).__name__,
                why=f"{'; '.join(p.message for p in error.problems)}: robosuite refuses the robot",
                fix=(
                    "name one of robosuite's configurations, a readable .json file, or give type and "
                    "body_parts"
                ),
                location=location,
            )
