"""``assemble``: a robot with its base and grippers, by name, as robosuite's ``Robot.load_model`` does."""

from __future__ import annotations

from collections.abc import Mapping

from assembler.errors import AssemblerError
from assembler.models import ManipulatorModel, RobotModel
from assembler.overrides import Overrides
from assembler.registry import create_base, create_gripper, create_robot

DEFAULT = "default"
"""Use the robot spec's default base or gripper."""


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
    change the robot's spec fields for this assembly only (see :func:`assembler.create_robot`)."""
    model = create_robot(robot, idn=idn, overrides=overrides)
    return equip(model, base, grippers)


def equip(
    model: RobotModel, base: str | None = DEFAULT, grippers: Mapping[str, str | None] | None = None
) -> RobotModel:
    """Give a created robot its base and grippers as :func:`assemble` does (same defaults and idn)."""
    robot, idn = type(model).__name__, model.idn
    base_name = model.default_base if base == DEFAULT else base
    if base_name is not None:
        model.add_base(create_base(base_name, idn=idn))
    if not isinstance(model, ManipulatorModel):
        if grippers:
            raise AssemblerError(f"{robot} has no arms to put grippers on")
        return model
    chosen: dict[str, str | None] = {arm: model.spec.default_grippers.get(arm) for arm in model.arms}  # type: ignore[call-overload]
    for arm, gripper in (grippers or {}).items():
        if arm not in chosen:
            raise AssemblerError(f"{robot} has no {arm} arm; its arms: {', '.join(model.arms)}")
        chosen[arm] = gripper
    for arm, gripper in chosen.items():
        if gripper is not None:
            model.add_gripper(create_gripper(gripper, idn=f"{idn}_{arm}"), arm)
    return model
