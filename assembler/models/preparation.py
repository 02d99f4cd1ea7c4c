"""A part's MJCF made ready to attach: what the spec removes and adds, and its joint values.

Steps, once per part instance: drop the file's keyframes (the assembler writes one merged ``home``
keyframe), remove the actuation of the joints the spec names (with everything driving or measuring
them), remove the free joint if asked, add the spec's joints, add the actuators and contact
exclusions the spec declares, then resolve every joint parameter (MJCF value, spec rule, spec
override) with its source, and put the spec's motors on their joints (values and actuators).
"""

from __future__ import annotations

from dataclasses import dataclass

import mujoco

from assembler.errors import MjcfError, Problem, SpecError, summarize_names
from assembler.mjcf.joints import (
    add_free_joint,
    add_joints,
    joint_attribute,
    named_joints,
    remove_bodies,
    remove_free_joints,
    remove_joints,
)
from assembler.mjcf.source import MjcfSource, root_body_name
from assembler.models.actuator_table import ActuatorRecord, declare_actuators
from assembler.models.joint_rules import (
    JointTable,
    JointValue,
    SpecProblem,
    apply_default_rules,
    apply_joint_overrides,
    matching_joints,
    no_match,
)
from assembler.models.motor_joints import add_motor_actuators, apply_motor_values, motor_drives
from assembler.models.physical import PhysicalTable, resolve_physical
from assembler.models.provenance import Provenance
from assembler.models.spec_names import NameCheck
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import JOINT_RULE_ATTRIBUTES, PartSpec

SETTABLE_JOINT_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")
"""Attributes ``set_joint_attribute`` accepts: the ones whose MJCF origin the assembler tracks."""

REMOVE_ACTUATION = FieldPath(("remove_actuation",))
CONTACT_EXCLUDES = FieldPath(("contact_excludes",))


@dataclass
class PreparedPart:
    """What a part knows once its MJCF is read: the file, the prepared MjSpec, its joints and their values."""

    source: MjcfSource
    mjspec: mujoco.MjSpec
    """The file's spec after the spec's removals and additions (never compiled or attached)."""

    root_name: str
    """The part's single root body, as named in the MJCF."""

    joint_names: list[str]
    """The part's joints after removals, MuJoCo's order, free joints excluded."""

    joint_values: JointTable
    """Each joint's frictionloss, damping, armature (and what else the file sets), with sources."""

    actuators: list[ActuatorRecord]
    """Every actuator of the part: the file's, then those the spec declares, with their values' sources."""

    physical: PhysicalTable
    """The bodies' mass and size factors and the geoms' frictions the spec's ``bodies:``/``geoms:`` give."""


def removed_joints(
    spec: PartSpec, source: MjcfSource, problem: SpecProblem
) -> tuple[list[str], list[Problem]]:
    """The joints ``remove_actuation`` names (globs expanded), and a problem per pattern matching nothing."""
    patterns: list[str] = list(getattr(spec, "remove_actuation", []))
    names = source.joint_names
    removed: list[str] = []
    problems = []
    for index, pattern in enumerate(patterns):
        matched = matching_joints(pattern, names)
        if not matched:
            problems.append(problem(REMOVE_ACTUATION.child(index), no_match(pattern, names)))
        removed += [name for name in matched if name not in removed]
    return removed, problems


def prepared_mjspec(
    spec: PartSpec, source: MjcfSource, removed: list[str], problem: SpecProblem
) -> mujoco.MjSpec:
    """A fresh copy of the file's spec with the spec's removals and additions applied."""
    mjspec = source.new_spec()
    for key in list(mjspec.keys):  # the assembler writes one merged "home" keyframe instead
        mjspec.delete(key)
    remove_joints(mjspec, removed)
    remove_bodies(mjspec, getattr(spec, "remove_bodies", []))
    if getattr(spec, "remove_free_joint", False):
        remove_free_joints(mjspec)
    if getattr(spec, "add_free_joint", False):
        try:
            add_free_joint(mjspec)
        except MjcfError as error:
            path = FieldPath(("add_free_joint",))
            raise MjcfError([problem(path, p.message) for p in error.problems]) from None
    try:
        add_joints(mjspec, getattr(spec, "added_joints", []))
    except MjcfError as error:
        path = FieldPath(("added_joints",))
        raise MjcfError([problem(path, p.message) for p in error.problems]) from None
    return mjspec


def add_contact_excludes(spec: PartSpec, mjspec: mujoco.MjSpec, problem: SpecProblem) -> list[Problem]:
    """One ``<exclude>`` per ``contact_excludes`` pair; a problem per missing body (then none is added)."""
    check = NameCheck(problem, mjspec, [])
    for index, pair in enumerate(spec.contact_excludes):
        for side, name in enumerate(pair):
            check.body(CONTACT_EXCLUDES.child(index).child(side), name)
    if not check.problems:
        for first, second in spec.contact_excludes:
            exclude = mjspec.add_exclude()
            exclude.bodyname1, exclude.bodyname2 = first, second
    return check.problems


def joint_table(spec: PartSpec, source: MjcfSource, kept: list[str], problem: SpecProblem) -> JointTable:
    """Every joint parameter of the kept joints, with its source: the file's, the rules', the spec's
    ``joints:`` and added joints', then the motors' (:mod:`assembler.models.motor_joints`)."""
    # Rules index over every joint of the file, before removals (robosuite applies its defaults
    # before removing actuation, so GR1ArmsOnly keeps the armature of its original indices).
    names = source.joint_names
    pristine = {j.name: j for j in source.pristine.joints}
    in_file = [{a: joint_attribute(pristine[n], a) for a in SETTABLE_JOINT_ATTRIBUTES} for n in names]
    authored_by_name = dict(zip((j.name for j in source.pristine.joints), source.authored, strict=True))
    authored = [authored_by_name[n] for n in names]
    table = apply_default_rules(names, in_file, authored, spec.joint_defaults, problem)
    table = {name: values for name, values in table.items() if name in kept}
    for index, added in enumerate(getattr(spec, "added_joints", [])):
        origin = Provenance("added", index=index)
        table[added.name] = {a: JointValue(float(getattr(added, a)), origin) for a in JOINT_RULE_ATTRIBUTES}
    apply_joint_overrides(table, kept, spec.joints, problem)
    if spec.motors:  # the motors' values last: they yield only to the spec's own word for a joint
        drives, problems = motor_drives(source.pristine, spec.motors, problem, kept)
        if problems:
            raise SpecError(problems)
        apply_motor_values(table, drives)
    return table


def init_qpos_problems(spec: PartSpec, joint_names: list[str], problem: SpecProblem) -> list[Problem]:
    """``init_qpos`` must give one value per joint."""
    init_qpos = spec.init_qpos
    if init_qpos is None or len(init_qpos) == len(joint_names):
        return []
    names = summarize_names(joint_names)
    message = f"expected {len(joint_names)} values (one per joint: {names}), got {len(init_qpos)}"
    return [problem(FieldPath(("init_qpos",)), message)]


def prepare(spec: PartSpec, source: MjcfSource, problem: SpecProblem) -> tuple[PreparedPart, list[Problem]]:
    """All preparation steps of one part, and the problems of the spec they found (the part is not
    usable when there are any; they are returned so that every problem can be reported at once)."""
    try:
        root = root_body_name(source)
    except MjcfError as error:
        model_file = FieldPath((spec.source_field,))
        raise MjcfError([problem(model_file, p.message) for p in error.problems]) from None
    removed, problems = removed_joints(spec, source, problem)
    for index, name in enumerate(getattr(spec, "remove_bodies", [])):
        if source.pristine.body(name) is None:
            problems.append(
                problem(FieldPath(("remove_bodies", index)), f"no body named '{name}' in the MJCF")
            )
    mjspec = prepared_mjspec(spec, source, removed, problem)
    kept = named_joints(mjspec)
    actuators, declared = declare_actuators(mjspec, spec.actuators, source.velocity_limits, problem)
    problems += declared + add_contact_excludes(spec, mjspec, problem)
    physical, physical_problems = resolve_physical(mjspec, spec.bodies, spec.geoms, problem)
    problems += physical_problems
    try:
        table = joint_table(spec, source, kept, problem)
    except SpecError as error:
        problems += error.problems
        table = {}
    drives, motor_problems = motor_drives(mjspec, spec.motors, problem)
    problems += [p for p in motor_problems if p not in problems]  # joint_table reports them too
    if drives and not motor_problems:
        actuators, motor_problems = add_motor_actuators(mjspec, actuators, drives, problem)
        problems += motor_problems
    return PreparedPart(source, mjspec, root, kept, table, actuators, physical), problems
