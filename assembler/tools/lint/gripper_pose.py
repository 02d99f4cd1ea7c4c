"""RA102: a gripper whose root body sits far from the hand it is mounted on.

A gripper keeps the pose its file gives its root body, relative to the hand (robosuite's grippers
are written that way, a few centimetres at most). A hand exported inside a scene carries its place
in that scene instead (gymnasium-robotics' Shadow hand: 1.6 m), and then floats away from the arm,
which MuJoCo compiles and simulates without a word.
"""

from __future__ import annotations

from collections.abc import Iterator

import numpy as np

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.models import GripperModel, ManipulatorModel
from assembler.spec.fieldpath import FieldPath

ROOT_OFFSET_LIMIT = 0.2
"""Metres between a gripper's root and its hand beyond which the root's pose is not a mount offset
(robosuite's grippers: 0.062 m at most, Robotiq 140's)."""


def _mounted(target: LintTarget) -> Iterator[tuple[GripperModel, str]]:
    """Each gripper of the target and the body it hangs from (the world for a gripper alone)."""
    robot = target.parts[0]
    if isinstance(robot, ManipulatorModel):
        for arm, gripper in robot.grippers.items():
            yield gripper, robot.eef_name[arm]
    elif isinstance(robot, GripperModel):
        yield robot, "world"


def gripper_root_far_from_hand(target: LintTarget) -> Iterator[Finding]:
    """RA102 (warning): a gripper's root body lies more than 0.2 m from the hand it is mounted on."""
    for gripper, hand in _mounted(target):
        offset = target.data.body(gripper.root_body).xpos - target.data.body(hand).xpos
        distance = float(np.linalg.norm(offset))
        if distance <= ROOT_OFFSET_LIMIT:
            continue
        yield Finding(
            code="RA102",
            severity="warning",
            subject=gripper.root_body,
            why=(
                f"the gripper's root body lies {distance:.3g} m from {hand}, where it is mounted: its file "
                "places it elsewhere (in a scene?), and the gripper floats away from the arm"
            ),
            fix=(
                "set root_pose: reset in the gripper's spec (its root at the hand's origin), or give the "
                "robot's gripper_mount the pose it should have"
            ),
            location=target.spec_location(gripper, FieldPath(("root_pose",))),
        )
