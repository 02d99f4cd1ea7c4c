"""The parity cases: every robosuite robot with its defaults, every gripper on every robot, every base
on five arms, and what a user does afterwards (another idn, placement, joint attributes); and, for
each case, the exact differences robosuite's mistakes cause (docs/robosuite-parity.md, D1-D5; D6 has its own test).
"""

from __future__ import annotations

import assembler
from tests.parity.case import Case, joint_attribute_values
from tests.parity.oracle import show

ROBOSUITE = "package://robosuite/"


def robosuite_names(registry: dict[str, type[assembler.models.PartModel]]) -> list[str]:
    """The registered parts read from robosuite's package, by name."""
    return sorted(name for name, cls in registry.items() if cls.spec.source_file.startswith(ROBOSUITE))


ROBOTS = robosuite_names(assembler.REGISTERED_ROBOTS)
GRIPPERS = robosuite_names(assembler.REGISTERED_GRIPPERS)
BASES = robosuite_names(assembler.REGISTERED_BASES)
BASE_ROBOTS = ("Panda", "Sawyer", "UR5e", "Kinova3", "XArm7")
"""The arms every base is tried on (robosuite's single-arm robots of different makers)."""

PLACE = {"xpos": (0.3, -0.2, 0.1), "ori": (0.3, -0.5, 1.2)}
"""A placement with a rotation about every axis (roll, pitch and yaw all non-zero)."""

DEFAULTS = [Case(robot) for robot in ROBOTS]
WITH_GRIPPERS = [Case(robot, gripper=gripper) for robot in ROBOTS for gripper in GRIPPERS]
ON_BASES = [Case(robot, base=base) for robot in BASE_ROBOTS for base in BASES]
IN_USE = (
    [Case("Sawyer", idn=1), Case("Baxter", idn="b"), Case("PandaOmron", idn="mobile_1")]
    + [Case("SpotWithArm", idn=2), Case("GR1", idn="g"), Case("Kinova3", base="Spot", idn=4)]
    + [Case(robot, **PLACE) for robot in ("Panda", "Baxter", "PandaOmron", "Tiago", "GR1FloatingBody")]
    + [Case(robot, **PLACE) for robot in ("SpotWithArm", "SpotWithArmFloating", "IIWA")]
    + [Case("XArm7", base="NullMobileBase", idn="x", **PLACE), Case("UR5e", base="NullBase", **PLACE)]
    + [Case(robot, joint_attribute=("stiffness", False)) for robot in ("Panda", "GR1", "Tiago")]
    + [Case(robot, joint_attribute=("damping", False)) for robot in ("Jaco", "Baxter", "PandaOmron")]
    + [Case(robot, joint_attribute=("frictionloss", True)) for robot in ("IIWA", "Sawyer")]
    + [Case(robot, joint_attribute=("armature", True)) for robot in ("Kinova3", "PandaDexRH")]
    + [Case("SpotWithArm", joint_attribute=("stiffness", True))]
    + [Case("UR5e", idn=7, joint_attribute=("damping", True), **PLACE)]
)
"""Another idn (int and text), placement with all three angles, ``set_joint_attribute`` (force True
and False) on a varied set of robots and bases. (Not on GR1ArmsOnly, GR1FixedLowerBody and
GR1FloatingBody, where robosuite's ``set_joint_attribute`` fails: D6, test_parity.py.)"""

ALL = DEFAULTS + WITH_GRIPPERS + ON_BASES + IN_USE


def _same_assembly(case: Case) -> tuple[object, ...]:
    robot = assembler.REGISTERED_ROBOTS[case.robot].spec
    grippers = tuple(case.gripper or robot.default_grippers.get(arm) for arm in robot.arms)
    return (case.robot, case.base_name, grippers, case.idn, case.xpos, case.ori, case.joint_attribute)


def same_assemblies(cases: list[Case]) -> list[list[Case]]:
    """The cases grouped by what they assemble (by our defaults), in order of first appearance:
    Panda, Panda with PandaGripper and Panda on RethinkMount are one group, one robosuite compile."""
    groups: dict[tuple[object, ...], list[Case]] = {}
    for case in cases:
        groups.setdefault(_same_assembly(case), []).append(case)
    return list(groups.values())


def mount(case: Case) -> str:
    return f"robot{case.idn}_manipulator_mount"


def renamed(case: Case) -> dict[str, str | None]:
    """Our body names robosuite names differently (D1) or does not have (D2)."""
    if case.base_type == "mobile":
        return {mount(case): "manipulator_mount"}
    if case.base_type == "legged":
        return {mount(case): None}
    return {}


_CAMERA_LEFT_BEHIND = [
    "camera {p}robotview: body {leg}support != {p}base",
    "camera {p}robotview: world position [1.292 0.    0.588] != [1.  0.  0.4]",
]
LEFT_BEHIND: dict[str, list[str]] = {
    robot: _CAMERA_LEFT_BEHIND for robot in ("IIWA", "Panda", "Sawyer", "UR5e", "Kinova3")
} | {
    "XArm7": _CAMERA_LEFT_BEHIND
    + ["geom {leg}support/geom[0]: only ours", "geom {p}base/geom[0]: only robosuite"],  # link_base mesh
}
"""D3: per robot, what robosuite leaves on the robot's outer body on a legged base (the root's
children other than its first body); ``{p}`` is the robot's prefix, ``{leg}`` the base's."""


def expected(case: Case) -> list[str]:
    """The differences case ``case`` must show, exactly: its documented deviations."""
    return sorted(line for _, line in deviations(case))


def deviations(case: Case) -> list[tuple[str, str]]:
    """(deviation, difference line) of the case, e.g. ("D1", "body robot0_manipulator_mount: ...")."""
    found: list[tuple[str, str]] = []
    if case.base_type == "mobile":
        found.append(("D1", f"body {mount(case)}: named manipulator_mount in robosuite"))
    if case.base_type == "legged":
        found.append(("D2", f"body {mount(case)}: not in robosuite"))
        names = {"p": f"robot{case.idn}_", "leg": f"leg{case.idn}_"}
        found += [("D3", line.format(**names)) for line in LEFT_BEHIND.get(case.robot, [])]
    if case.base_name == "SpotFloating":
        leg = f"leg{case.idn}_"
        found.append(("D4", f"joint {leg}joint_mobile_forward: axis [1. 0. 0.] != [0. 1. 0.]"))
        found.append(("D4", f"joint {leg}joint_mobile_side: axis [0. 1. 0.] != [1. 0. 0.]"))
    if case.base_type in ("mobile", "legged") and case.joint_attribute is not None:
        found += [("D5", line) for line in _joint_attribute_dropped(case)]
    return found


def _joint_attribute_dropped(case: Case) -> list[str]:
    """D5: on a mobile or legged base robosuite's ``set_joint_attribute`` changes nothing, so each
    joint we give a new stiffness keeps the stiffness of robosuite's file (none: 0)."""
    attribute, force = case.joint_attribute or ("", False)
    robot = assembler.create_robot(case.robot, idn=case.idn)
    if attribute == "stiffness":  # set on every joint, force or not: the files give none
        values = joint_attribute_values(robot.dof)
        return [
            f"joint {joint}: stiffness {show(v)} != 0" for joint, v in zip(robot.joints, values, strict=True)
        ]
    if force:
        raise NotImplementedError(f"{case.id}: write down which joints D5 changes for {attribute}")
    return []  # force=False on an attribute every joint already has: no change on either side
