"""Resolve every joint parameter the spec controls, remembering where each final value came from.

The order is robosuite's, made explicit:
1. the MJCF's own value, where the file sets the attribute (MuJoCo's default resolution decides);
2. the spec's default rule (robosuite: frictionloss 0.1, damping 0.1, armature 5.0/(i+1)) elsewhere;
3. the spec's per-joint overrides, in order (``force: false`` leaves the MJCF's values alone).

Index ``i`` counts the robot's own joints in MuJoCo's order (free joints excluded). On every robot
file robosuite ships this equals robosuite's XML document order.
"""

from __future__ import annotations

import fnmatch
from collections.abc import Callable, Sequence
from dataclasses import dataclass

from assembler.errors import Location, Problem, SpecError, summarize_names
from assembler.schema import JOINT_RULE_ATTRIBUTES, InverseIndexRule, JointDefaults, JointOverride
from assembler.yaml_source import DataPath, dotted

FROM_MJCF = "mjcf"


@dataclass(frozen=True)
class JointValue:
    """A joint parameter's final value and its source, e.g. ``rule 5.0/(i+1)`` or ``mjcf (literal)``."""

    value: float
    source: str


JointTable = dict[str, dict[str, JointValue]]
"""Joint name (unprefixed) -> attribute -> value and source."""

Locator = Callable[[DataPath], Location]


def _rule_values(attribute: str, rule: object, count: int, locate: Locator) -> tuple[list[float], str] | None:
    if rule is None:
        return None
    if isinstance(rule, InverseIndexRule):
        scale = rule.inverse_index
        return [scale / (i + 1) for i in range(count)], f"rule {scale:g}/(i+1)"
    if isinstance(rule, list):
        if len(rule) != count:
            path = ("joint_defaults", attribute)
            raise SpecError(
                Problem(
                    f"expected {count} values (one per joint), got {len(rule)}",
                    locate(path),
                    dotted(path),
                )
            )
        return [float(v) for v in rule], "rule (list)"
    return [float(rule)] * count, f"rule {float(rule):g}"  # type: ignore[arg-type]


def apply_default_rules(
    joint_names: Sequence[str],
    mjcf_values: Sequence[dict[str, float]],
    authored: Sequence[dict[str, str]],
    defaults: JointDefaults,
    locate: Locator,
) -> JointTable:
    """Steps 1 and 2: the MJCF's values where it sets them, the rules elsewhere."""
    table: JointTable = {name: {} for name in joint_names}
    for attribute in JOINT_RULE_ATTRIBUTES:
        rule = _rule_values(attribute, getattr(defaults, attribute), len(joint_names), locate)
        for i, name in enumerate(joint_names):
            how = authored[i].get(attribute)
            if how is not None:
                table[name][attribute] = JointValue(mjcf_values[i][attribute], f"{FROM_MJCF} ({how})")
            elif rule is not None:
                table[name][attribute] = JointValue(rule[0][i], rule[1])
    # Attributes without a rule that the file sets (e.g. stiffness) are reported too.
    for i, name in enumerate(joint_names):
        for attribute, how in authored[i].items():
            table[name].setdefault(attribute, JointValue(mjcf_values[i][attribute], f"{FROM_MJCF} ({how})"))
    return table


def matching_joints(pattern: str, joint_names: Sequence[str]) -> list[str]:
    """Joints named exactly ``pattern``, or matching it as a glob (``*``, ``?``, ``[...]``)."""
    if pattern in joint_names:
        return [pattern]
    return [name for name in joint_names if fnmatch.fnmatchcase(name, pattern)]


def apply_overrides(
    table: JointTable,
    joint_names: Sequence[str],
    overrides: Sequence[JointOverride],
    locate: Locator,
) -> None:
    """Step 3: each override sets its attributes on the joints it matches (all problems at once)."""
    problems = []
    for index, override in enumerate(overrides):
        matched = matching_joints(override.match, joint_names)
        if not matched:
            path = ("joints", index, "match")
            problems.append(
                Problem(
                    f"no joint matches '{override.match}'. Joints: {summarize_names(list(joint_names))}",
                    locate(path),
                    dotted(path),
                )
            )
            continue
        for name in matched:
            for attribute, value in override.values().items():
                current = table[name].get(attribute)
                from_file = current is not None and current.source.startswith(FROM_MJCF)
                if override.force or not from_file:
                    table[name][attribute] = JointValue(value, f"spec joints[{index}]")
    if problems:
        raise SpecError(problems)
