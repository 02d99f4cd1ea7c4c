"""RA702-RA703: what robosuite's environments ask of a gripper beyond its model.

robosuite finds a gripper's frame by a body named ``eef`` and its grip point by the sites
``grip_site`` and ``grip_site_cylinder``; where a gripper lacks them, the bridge adds them at the
spec's ``eef_body`` for robosuite (RA702 says so, as info). A gripper's ``format_action`` turns a
policy's actions into actuator controls; ours follows the spec's ``actions:``, and robosuite
refuses a gripper with actuators that declares none (RA703). These checks read our model only.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.models import GripperModel
from assembler.robosuite.conventions import GRIP_FRAMES, grip_sensors
from assembler.spec.fieldpath import FieldPath
from assembler.tools.lint.finding import Finding
from assembler.tools.lint.target import LintTarget


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
