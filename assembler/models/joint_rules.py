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

from assembler.errors import Problem, SpecError, did_you_mean, summarize_names
from assembler.mjcf.joints import Authored
from assembler.models.provenance import Provenance
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import JOINT_RULE_ATTRIBUTES, InverseIndexRule, JointDefaults, JointOverride


@dataclass(frozen=True)
class JointValue:
    """A joint parameter's final value and where it came from."""

    value: float
    source: Provenance


JointTable = dict[str, dict[str, JointValue]]
"""Joint name (unprefixed) -> attribute -> value and source."""

SpecProblem = Callable[[FieldPath, str], Problem]
"""Makes a problem located at a field of the part's spec."""


def _rule_values(
    attribute: str, rule: object, count: int, problem: SpecProblem
) -> tuple[list[float], Provenance] | None:
    if rule is None:
        return None
    if isinstance(rule, InverseIndexRule):
        scale = rule.inverse_index
        return [scale / (i + 1) for i in range(count)], Provenance(
            "rule", rule=f"{scale:g}/(i+1)", inverse_index=scale
        )
    if isinstance(rule, list):
        if len(rule) != count:
            path = FieldPath(("joint_defaults", attribute))
            raise SpecError(problem(path, f"expected {count} values (one per joint), got {len(rule)}"))
        return [float(v) for v in rule], Provenance("rule", rule="(list)")
    return [float(rule)] * count, Provenance("rule", rule=f"{float(rule):g}")  # type: ignore[arg-type]


def _from_file(authored: tuple[str, str]) -> Provenance:
    how, class_name = authored
    return Provenance("mjcf", how=how, class_name=class_name)  # type: ignore[arg-type]


def apply_default_rules(
    joint_names: Sequence[str],
    mjcf_values: Sequence[dict[str, float]],
    authored: Sequence[Authored],
    defaults: JointDefaults,
    problem: SpecProblem,
) -> JointTable:
    """Steps 1 and 2: the MJCF's values where it sets them, the rules elsewhere."""
    table: JointTable = {name: {} for name in joint_names}
    for attribute in JOINT_RULE_ATTRIBUTES:
        rule = _rule_values(attribute, getattr(defaults, attribute), len(joint_names), problem)
        for i, name in enumerate(joint_names):
            how = authored[i].get(attribute)
            if how is not None:
                table[name][attribute] = JointValue(mjcf_values[i][attribute], _from_file(how))
            elif rule is not None:
                table[name][attribute] = JointValue(rule[0][i], rule[1])
    # Attributes without a rule that the file sets (e.g. stiffness) are reported too.
    for i, name in enumerate(joint_names):
        for attribute, how in authored[i].items():
            table[name].setdefault(attribute, JointValue(mjcf_values[i][attribute], _from_file(how)))
    return table


def matching_joints(pattern: str, joint_names: Sequence[str]) -> list[str]:
    """Joints named exactly ``pattern``, or matching it as a glob (``*``, ``?``, ``[...]``)."""
    if pattern in joint_names:
        return [pattern]
    return [name for name in joint_names if fnmatch.fnmatchcase(name, pattern)]


def no_match(pattern: str, names: Sequence[str], what: str = "joint", plural: str = "") -> str:
    """The one wording of a name or glob that matches nothing, with the closest name."""
    suggestion = did_you_mean(pattern, names)
    listed = (plural or f"{what}s").capitalize()
    return f"no {what} matches '{pattern}'.{suggestion} {listed}: {summarize_names(list(names))}"


def apply_joint_overrides(
    table: JointTable,
    joint_names: Sequence[str],
    overrides: Sequence[JointOverride],
    problem: SpecProblem,
) -> None:
    """Step 3: each override sets its attributes on the joints it matches (all problems at once)."""
    problems = []
    for index, override in enumerate(overrides):
        matched = matching_joints(override.match, joint_names)
        if not matched:
            problems.append(
                problem(FieldPath(("joints", index, "match")), no_match(override.match, joint_names))
            )
            continue
        for name in matched:
            for attribute, value in override.values().items():
                current = table[name].get(attribute)
                if override.force or current is None or not current.source.from_file:
                    table[name][attribute] = JointValue(value, Provenance("override", index=index))
    if problems:
        raise SpecError(problems)
