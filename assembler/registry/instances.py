"""Making instances: a robot, base or gripper by registered name, and a robot with its base and
grippers as robosuite's ``Robot.load_model`` assembles it."""

from __future__ import annotations

from collections.abc import Mapping

from assembler.errors import AssemblerError, Problem, RegistryError
from assembler.models import (
    REGISTERED_BASES,
    REGISTERED_GRIPPERS,
    REGISTERED_ROBOTS,
    GripperModel,
    ManipulatorModel,
    RobotBaseModel,
    RobotModel,
)
from assembler.registry.catalog import with_overrides
from assembler.spec.documents import Overrides
from assembler.spec.fieldpath import FieldPath
from assembler.spec.part_arguments import DEFAULT


def create_robot(robot_name: str, *args: object, overrides: Overrides = None, **kwargs: object) -> RobotModel:
    """An instance of the registered robot ``robot_name``, e.g. ``create_robot("Sparrow7", idn=1)``.

    ``overrides`` (``{"joint_defaults.damping": 0.2}`` or ``["init_qpos[3]=-2.0"]``) change spec
    fields for this instance only; the registered class is left as it is."""
    return robot_class(robot_name, overrides)(*args, **kwargs)  # type: ignore[arg-type]


def robot_class(robot_name: str, overrides: Overrides = None) -> type[RobotModel]:
    """The class of :func:`create_robot`'s robot: the registered one, or its variant with ``overrides``."""
    return with_overrides(REGISTERED_ROBOTS.lookup(robot_name), overrides)


def create_base(base_name: str, idn: int | str = 0) -> RobotBaseModel:
    """An instance of the registered base ``base_name``."""
    return REGISTERED_BASES.lookup(base_name)(idn=idn)


def create_gripper(gripper_name: str, idn: int | str = 0) -> GripperModel:
    """An instance of the registered gripper ``gripper_name``; robots pass ``idn="{robot_idn}_{arm}"``."""
    return REGISTERED_GRIPPERS.lookup(gripper_name)(idn=idn)


def assemble(
    robot: str,
    idn: int | str = 0,
    base: str | None = DEFAULT,
    grippers: Mapping[str, str | None] | None = None,
    overrides: Overrides = None,
) -> RobotModel:
    """Create robot ``robot`` with a base (its default unless given; None for none) and a gripper per
    arm (its defaults, replaced per arm by ``grippers``; None for none). Grippers get idn
    ``"{idn}_{arm}"``, so their prefix is e.g. ``gripper0_right_``, as in robosuite. ``overrides``
    change the robot's spec fields for this assembly only (see :func:`create_robot`)."""
    model = create_robot(robot, idn=idn, overrides=overrides)
    return equip(model, base, grippers)


def _from_spec_default(model: RobotModel, path: FieldPath, error: RegistryError) -> list[Problem]:
    """A registry miss for a name the robot's spec gave by default, located at that field."""
    return [model.spec_problem(path, p.message) for p in error.problems]


def equip(
    model: RobotModel, base: str | None = DEFAULT, grippers: Mapping[str, str | None] | None = None
) -> RobotModel:
    """Give a created robot its base and grippers as :func:`assemble` does (same defaults and idn);
    every unknown name at once, those the robot's spec gave at their spec field."""
    robot, idn = type(model).__name__, model.idn
    problems: list[Problem] = []
    base_name = model.default_base if base == DEFAULT else base
    if base_name is not None:
        try:
            model.add_base(create_base(base_name, idn=idn))
        except RegistryError as error:
            if base != DEFAULT:
                raise
            problems += _from_spec_default(model, FieldPath(("default_base",)), error)
    if not isinstance(model, ManipulatorModel):
        if grippers:
            raise AssemblerError(f"{robot} has no arms to put grippers on")
        if problems:
            raise RegistryError(problems)
        return model
    chosen: dict[str, str | None] = {arm: model.spec.default_grippers.get(arm) for arm in model.arms}  # type: ignore[call-overload]
    given = dict(grippers or {})
    for arm in given:
        if arm not in chosen:
            raise AssemblerError(f"{robot} has no {arm} arm; its arms: {', '.join(model.arms)}")
    chosen.update(given)
    for arm, gripper in chosen.items():
        if gripper is None:
            continue
        try:
            model.add_gripper(create_gripper(gripper, idn=f"{idn}_{arm}"), arm)
        except RegistryError as error:
            if arm in given:
                raise
            problems += _from_spec_default(model, FieldPath(("default_grippers", arm)), error)
    if problems:
        raise RegistryError(problems)
    return model
