"""What a patch compares: a robot's spec and its resolved joint, actuator and ``bodies:``/``geoms:`` tables.

:meth:`Resolved.of` reads them from a built robot. :func:`resolve_variant` resolves a variant's
spec against the robot it varies without preparing the variant's MJCF again (the tables are
functions of the spec and the file, which the two share): a thousand variants cost a thousand
spec validations, not a thousand MJCF preparations. A variant that changes anything else is
prepared in full, and the patch then says whether it is structural.
"""

from __future__ import annotations

import copy
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import mujoco
from pydantic import ValidationError

from assembler.errors import SpecError
from assembler.models import RobotModel
from assembler.models.joint_rules import JointTable
from assembler.models.physical import PhysicalTable, element_names, resolve_physical
from assembler.models.preparation import init_qpos_problems, joint_table
from assembler.registry.catalog import with_overrides
from assembler.registry.instances import assemble
from assembler.spec.documents import Override, blame
from assembler.spec.part_arguments import DEFAULT
from assembler.spec.schema import RobotSpec

LIGHT_SECTIONS = frozenset({"joint_defaults", "joints", "bodies", "geoms", "init_qpos"})
"""Spec fields a variant may change and still be resolved against the robot's prepared MJCF."""


@dataclass(frozen=True)
class Resolved:
    """A robot's spec and its tables, unprefixed, as ``assembler.patch.patchable.model_patch`` reads them."""

    spec: RobotSpec
    prefix: str
    joint_names: list[str]
    joint_values: JointTable
    physical: PhysicalTable
    actuators: Sequence[mujoco.MjsActuator]
    """The robot part's actuators as its prepared MJCF has them (uncompiled: a dampratio is positive);
    a variant resolved against its robot shares the robot's list."""

    dump: dict[str, Any]
    """``spec.model_dump()``, made once: patches compare the fields they cannot patch."""

    names: tuple[list[str], list[str]]
    """The robot part's named bodies and geoms (what ``bodies:`` and ``geoms:`` match), read once."""

    owner: mujoco.MjSpec
    """The prepared spec holding ``actuators``: kept alive with them (MuJoCo 3.9's bindings free the
    elements of a spec nothing refers to)."""

    @classmethod
    def of(cls, robot: RobotModel) -> Resolved:
        """The tables of a built robot (its MJCF prepared if it was not)."""
        return cls(
            robot.spec,
            robot.naming_prefix,
            robot.joint_names,
            robot.joint_values,
            robot.physical,
            list(robot.prepared_mjspec.actuators),
            robot.spec.model_dump(),
            element_names(robot.prepared_mjspec),
            robot.prepared_mjspec,
        )


def _quick_spec(resolved: Resolved, overrides: Sequence[Override]) -> RobotSpec | None:
    """The robot's spec with ``overrides`` put into its dump and validated again, or None when that
    fails; cheaper than the document path (positions, inheritance), which reports the failure."""
    data = dict(resolved.dump)
    for override in overrides:
        container: Any = data
        try:
            for part in override.path[:-1]:  # copy what the path goes through; share the rest
                inner = container[part]
                container[part] = inner = dict(inner) if isinstance(inner, dict) else list(inner)
                container = inner
            container[override.path[-1]] = copy.deepcopy(override.value)
        except (KeyError, IndexError, TypeError):
            return None
    try:
        return type(resolved.spec).model_validate(data)
    except ValidationError:
        return None


def resolve_spec(
    base: RobotModel, resolved: Resolved, spec: RobotSpec, overrides: Sequence[Override]
) -> Resolved | None:
    """The tables of ``base``'s robot with its spec replaced by ``spec`` (``base``'s own spec with
    ``overrides``, which name any problem), resolved against ``base``'s prepared MJCF; None when
    ``spec`` changes more than the light sections (then the variant must be prepared in full)."""
    ours, theirs = resolved.dump, spec.model_dump()
    if any(ours[key] != theirs[key] for key in ours if key not in LIGHT_SECTIONS):
        return None
    prepared = base.prepared()
    problems = init_qpos_problems(spec, prepared.joint_names, type(base).spec_problem)
    try:
        joints = joint_table(spec, prepared.source, prepared.joint_names, type(base).spec_problem)
    except SpecError as error:
        problems += error.problems
        joints = {}
    physical, physical_problems = resolve_physical(
        prepared.mjspec, spec.bodies, spec.geoms, type(base).spec_problem, resolved.names
    )
    problems += physical_problems
    if problems:
        raise SpecError([blame(p, overrides, note=False) for p in problems])
    actuators = resolved.actuators
    names, owner = resolved.names, resolved.owner
    return Resolved(
        spec, resolved.prefix, prepared.joint_names, joints, physical, actuators, theirs, names, owner
    )


def resolve_variant(
    base: RobotModel,
    resolved: Resolved,
    overrides: Sequence[Override],
    grippers: Mapping[str, str | None] | None = None,
    base_name: str | None = DEFAULT,
) -> Resolved:
    """The tables of ``base``'s robot (``resolved`` are its own) with ``overrides`` (which may not be
    valid: a :class:`SpecError` names the override), resolved against ``base``'s prepared MJCF when
    only light sections change."""
    spec = _quick_spec(resolved, overrides)
    if spec is None:  # a value the schema refuses, or a path the dump lacks: the full path says why
        spec = with_overrides(type(base), overrides).spec
    light = resolve_spec(base, resolved, spec, overrides)
    if light is None:
        return Resolved.of(assemble(type(base).__name__, base.idn, base_name, grippers, overrides))
    return light
