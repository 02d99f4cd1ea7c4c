"""What a build must add to an assembly: every element of the robot's parts, as composition places them.

Each part contributes its prepared spec, i.e. its file minus what its own spec removes
(``remove_actuation``, ``remove_free_joint``; keyframes give way to ``home``; see
:mod:`assembler.models.part`). Composition then changes the counts in a few documented ways
(:mod:`assembler.mjcf.compose`), and only these:

- a null base contributes its sites only;
- a mobile or legged base adds an outer body that keeps the robot root's name, the robot's root
  loses its free joint, and a legged base's free joints give way to one free joint on that outer body.

After :meth:`RobotModel.build_into`, the assembly must have grown by at least this much in every
kind of :mod:`assembler.mjcf.census`; otherwise something was dropped in silence, which is a bug
(:class:`assembler.mjcf.census.ElementsLost`). "At least", not "exactly": a subclass may add
elements of its own (e.g. in ``_attach_grippers``), never lose any.
"""

from __future__ import annotations

from collections import Counter
from typing import TYPE_CHECKING

import mujoco

from assembler.mjcf import census
from assembler.mjcf.census import Census

if TYPE_CHECKING:
    from assembler.models.base_model import RobotBaseModel
    from assembler.models.part import PartModel
    from assembler.models.robot_model import RobotModel

FREE = mujoco.mjtJoint.mjJNT_FREE


def _free_joints(joints: list[mujoco.MjsJoint]) -> int:
    return sum(joint.type == FREE for joint in joints)


def _base_contribution(robot: RobotModel, base: RobotBaseModel) -> Census:
    if base.type == "null":
        return Counter({"sites": len(base.prepared.sites)})
    contribution = census.of_spec(base.prepared)
    if base.type in ("mobile", "legged"):
        contribution["bodies"] += 1  # the outer body, named as the robot's root
        robot_root = robot.prepared.worldbody.first_body()
        contribution["joints"] -= _free_joints(list(robot_root.joints))
        base_root = base.prepared.worldbody.first_body()
        if base.type == "legged" and _free_joints(list(base_root.joints)):
            contribution["joints"] += 1 - _free_joints(list(base.prepared.joints))
    return contribution


def robot_contribution(robot: RobotModel) -> Census:
    """What building ``robot`` (with its base and grippers) adds to an assembly, per kind."""
    total = census.of_spec(robot.prepared)
    if robot.base is not None:
        total.update(_base_contribution(robot, robot.base))
    grippers: dict[str, PartModel] = getattr(robot, "grippers", {})
    for gripper in grippers.values():
        total.update(census.of_spec(gripper.prepared))
    return total


def require_kept(robot: RobotModel, assembly: mujoco.MjSpec, before: Census) -> None:
    """``assembly`` (counted as ``before`` when the build began) now holds every element of
    ``robot``'s parts; :class:`~assembler.mjcf.census.ElementsLost` otherwise."""
    grown = census.of_spec(assembly)
    grown.subtract(before)
    census.require_at_least(grown, robot_contribution(robot), f"building robot '{type(robot).__name__}'")


def require_kept_alone(part: PartModel, assembly: mujoco.MjSpec) -> None:
    """``assembly``, built from ``part`` alone, holds every element of the part."""
    what = f"building {part.family} '{type(part).__name__}' alone"
    census.require_at_least(census.of_spec(assembly), census.of_spec(part.prepared), what)
