"""RA705-RA708: the rest of what ``assembler.robosuite`` refuses at ``robosuite.make``, found by lint.

RA701 and RA703 cover the bridge's refusals about actuators and gripper actions; these cover the
others a spec can provoke: a joint robosuite's controllers would drive with no actuator (RA705), a
``base_xpos_offset`` robosuite cannot read (RA706), euler angles in another sequence than robosuite's
world reads (RA707), and a ``robosuite.controller`` the bridge cannot build (RA708). Each asks the
bridge's own functions where they need no robosuite, so the two cannot disagree;
tests/tools/test_lint_bridge.py checks that every refusal in assembler/robosuite has its rule.
"""

from __future__ import annotations

import importlib
import importlib.util
from collections.abc import Iterator

from assembler.errors import SpecError
from assembler.models import ManipulatorModel
from assembler.robosuite.conventions import CONTROLLER
from assembler.robosuite.parts import undriven_joints
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema.expressions import ExpressionError
from assembler.tools.lint.finding import Finding
from assembler.tools.lint.target import LintTarget


def _offered(target: LintTarget) -> Iterator[ManipulatorModel]:
    """The target's robot when robosuite is offered it (robosuite.enabled)."""
    robot = target.parts[0] if target.parts else None
    if isinstance(robot, ManipulatorModel) and robot.spec.robosuite.enabled:
        yield robot


def undriven_controlled_joints(target: LintTarget) -> Iterator[Finding]:
    """RA705 (error): a joint of a group robosuite's controllers drive has no actuator."""
    for robot in _offered(target):
        undriven = undriven_joints(robot, robot.part_mjspec())
        if not undriven:
            continue
        yield Finding(
            code="RA705",
            severity="error",
            subject=type(robot).__name__,
            why=(
                "robosuite's controllers drive each joint of the groups they control with one actuator, "
                f"but {', '.join(undriven)} {'has' if len(undriven) == 1 else 'have'} none: "
                "robosuite refuses the robot"
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
