"""RA401: armature from robosuite's index rule that has shrunk too far along a long joint chain.

The rule ``armature = scale / (i + 1)`` was written for 7-joint arms; on a humanoid the 26th joint
gets 5/26 = 0.19, a value that has nothing to do with its motor (robosuite gives GR1's legs 0.16).
The assembler knows where each joint value came from, so only rule-given values are reported.
"""

from __future__ import annotations

from collections.abc import Iterator

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.spec.fieldpath import FieldPath

TINY_ARMATURE = 0.2
"""Rule-given armature (kg m^2) below this is reported: the rule, not the motor, chose it."""


def tiny_index_armature(target: LintTarget) -> Iterator[Finding]:
    """RA401 (warning): a joint's armature comes from the inverse-index rule and is below 0.2."""
    for part in target.parts:
        for joint, values in part.joint_values.items():
            armature = values.get("armature")
            from_rule = armature is not None and armature.source.inverse_index is not None
            if armature is None or not from_rule or armature.value >= TINY_ARMATURE:
                continue
            yield Finding(
                code="RA401",
                severity="warning",
                subject=part.naming_prefix + joint,
                why=(
                    f"armature {armature.value:.3g} comes from the index rule ({armature.source}), not from "
                    f"the joint's motor: the rule shrinks it along the chain below {TINY_ARMATURE:g}"
                ),
                fix=(
                    "set joint_defaults.armature to a value or a per-joint list that fits the motors, "
                    f"or give this joint its own under joints: (match: {joint})"
                ),
                location=target.spec_location(part, FieldPath(("joint_defaults", "armature"))),
            )
