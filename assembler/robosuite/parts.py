"""Our parts as robosuite's environments see them, and the MJCF files robosuite reads for them.

robosuite lists each part's elements by name from the file it reads, and the environment looks every
listed name up in the compiled world. So the file robosuite reads for a gripper or base and the
assembly our robot builds must name every element alike: a part made for robosuite
(:func:`robosuite_part`, an instance of our spec class, no class of its own) has an ``adaptation``
that gives unnamed geoms robosuite's names and, for a robot whose spec says
``robosuite.actuation: torque``, drives with torque motors what robosuite's controllers drive (its
position servos, and its DC motors driven in volts). The
text is the lossless emission, kept in the cache across processes (:mod:`.files`).
"""

from __future__ import annotations

import warnings
from typing import TypeVar

import mujoco

from assembler.errors import AssemblerWarning, SpecError
from assembler.mjcf.census import weighed_by_other_groups
from assembler.models import GripperModel, ManipulatorModel, PartModel, RobotModel
from assembler.models.collision_colour import colour_collision_geoms
from assembler.models.motor_joints import voltage_limits
from assembler.models.motor_rules import Derived
from assembler.robosuite.actuation import has_force_range, motorize, position_servos, torque_motors
from assembler.robosuite.arm_centers import add_arm_centers
from assembler.robosuite.conventions import (
    ACTUATION,
    DRIVEN_GROUPS,
    INERTIA_GROUPS,
    driven_actuators,
    robot_type_name,
)
from assembler.robosuite.files import robosuite_file
from assembler.robosuite.geom_names import name_geoms_as_robosuite
from assembler.robosuite.grip_frames import add_grip_frames
from assembler.spec.fieldpath import FieldPath

P = TypeVar("P", bound=PartModel)

JOINT_GROUPS = FieldPath(("joint_groups",))


def robosuite_part(cls: type[P], idn: int | str = 0) -> P:
    """A part of ``cls`` (our spec class) as robosuite's environments see it: an instance whose part
    spec gets :func:`as_robosuite_sees` (its ``adaptation``), which its cache keys name."""
    part = cls(idn=idn)
    part.adaptation = as_robosuite_sees
    return part


def as_robosuite_sees(part: PartModel, mjspec: mujoco.MjSpec) -> mujoco.MjSpec:
    """``mjspec`` (``part``'s own spec) with robosuite's geom names and collision colours, a robot's
    drives as its spec declares them and its arms' centres, a gripper's grip frames."""
    mjspec = name_geoms_as_robosuite(mjspec)
    if part.spec.collision_colour != "robosuite":
        # robosuite's XML layer colours every collision geom itself when it reads a part: given
        # that colour here, what robosuite reads is what we give (docs/robosuite.md)
        colour_collision_geoms(mjspec, part.collision_rgba)
    if isinstance(part, ManipulatorModel):
        drive_as_declared(part, mjspec)
        add_arm_centers(part, mjspec)
    if isinstance(part, GripperModel):
        add_grip_frames(part, mjspec)
    return mjspec


def drive_as_declared(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> None:
    """Apply the spec's ``robosuite.actuation`` to ``mjspec``, the robot's part spec (unprefixed)."""
    undriven = undriven_joints(robot, mjspec)
    if undriven:
        raise SpecError(
            robot.spec_problem(
                JOINT_GROUPS,
                f"robosuite's controllers drive each joint of the groups they control with one actuator, "
                f"but {', '.join(undriven)} {'has' if len(undriven) == 1 else 'have'} none "
                f"({why_undriven(undriven, mjspec)}): declare an actuator for each, "
                "or set robosuite.enabled: false for a robot robosuite cannot drive",
            )
        )
    driven = {name.removeprefix(robot.naming_prefix) for name in driven_actuators(robot)}
    servos = position_servos(mjspec, driven)
    choice = robot.spec.robosuite.actuation
    names = ", ".join(servo.name for servo in servos)
    if servos and choice is None:
        raise SpecError(
            robot.spec_problem(
                ACTUATION,
                f"the actuators {names} are position servos, but robosuite's controllers write torques into "
                "them: set robosuite.actuation to torque (each becomes a motor with the servo's forcerange "
                "as its ctrlrange) or to as_is (keep the servos)",
            )
        )
    voltage = driven_voltage_motors(robot)
    if voltage and choice is None:
        raise SpecError(
            robot.spec_problem(
                ACTUATION,
                f"the actuators {', '.join(voltage)} take volts (motors: control: voltage), but robosuite's "
                "controllers write torques into them: set robosuite.actuation to torque (each becomes a "
                "motor within its motor's torque limit, ±(peak or stall torque)·N·η) or to as_is "
                "(keep volts)",
            )
        )
    if choice == "torque":
        unbounded = [servo.name for servo in servos if not has_force_range(servo)]
        if unbounded:
            raise SpecError(
                robot.spec_problem(
                    ACTUATION,
                    f"robosuite.actuation is torque, but the position servos {', '.join(unbounded)} have "
                    "no forcerange to become the motor's ctrlrange; give each a forcerange in the MJCF",
                )
            )
        motorize(servos)
        torque_motors(mjspec, {name: limit.value for name, limit in voltage.items()})


def undriven_joints(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> list[str]:
    """The robot's own joints (unprefixed) in groups robosuite's controllers drive that no named actuator
    of ``mjspec`` (the robot's part spec) drives: robosuite finds each actuator by its name, so an
    unnamed one drives nothing for it (its controller would get no actuator for the joint)."""
    targets = {actuator.target for actuator in mjspec.actuators if actuator.name}
    driven = DRIVEN_GROUPS[robot_type_name(type(robot))]
    return [j for j in robot.joint_names if robot.group_of(j) in driven and j not in targets]


def why_undriven(undriven: list[str], mjspec: mujoco.MjSpec) -> str:
    """Why the ``undriven`` joints may have no actuator robosuite finds: unnamed actuators on them, or
    (none there) a URDF ``<mimic>`` follower, which no actuator drives."""
    unnamed = [j for j in undriven if any(a.target == j and not a.name for a in mjspec.actuators)]
    if not unnamed:
        return "a mimic follower?"
    return (
        f"the actuators of {', '.join(unnamed)} have no name, and robosuite finds an actuator by its name: "
        "name each in the MJCF, or through mjcf_fixes with set: {name: ...}"
    )


def part_file(part: PartModel) -> str:
    """The file robosuite reads for ``part`` alone (unprefixed: robosuite prefixes it)."""
    inputs = part.part_inputs()
    return robosuite_file(inputs, inputs.spec_made, [part], part.part_mjspec)


def assembly_file(robot: RobotModel) -> str:
    """The file robosuite reads for ``robot`` with its base and grippers (prefixed: our assembly)."""
    inputs = robot.build_inputs()
    return robosuite_file(inputs, inputs.cacheable, [robot, *robot.models], lambda: world_checked(robot))


def world_checked(robot: RobotModel) -> mujoco.MjSpec:
    """The robot's assembly, said where robosuite's world will weigh some body differently."""
    mjspec = robot.build_mjspec()
    bodies = weighed_by_other_groups(mjspec, INERTIA_GROUPS)
    if bodies:
        shown = ", ".join(bodies[:4]) + (f" and {len(bodies) - 4} more" if len(bodies) > 4 else "")
        warnings.warn(
            f"{type(robot).__name__}: robosuite's world counts only group-0 geoms in inferred masses "
            f'(<compiler inertiagrouprange="0 0">), so {shown} weigh less there than in the assembled '
            "model; give those bodies an <inertial> to make them agree",
            AssemblerWarning,
            stacklevel=2,
        )
    return mjspec


def driven_voltage_motors(robot: ManipulatorModel) -> dict[str, Derived]:
    """The actuators robosuite's controllers drive (unprefixed) that take volts (a ``motors:`` entry's
    ``control: voltage``) -> the joint torque limit, ±(peak or stall torque)·N·η, of the motor each
    becomes under ``robosuite.actuation: torque``."""
    driven = {name.removeprefix(robot.naming_prefix) for name in driven_actuators(robot)}
    limits = voltage_limits(robot.spec.motors, robot.actuator_table)
    return {name: limit for name, limit in limits.items() if name in driven}
