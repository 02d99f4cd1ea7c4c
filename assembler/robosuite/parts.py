"""Our parts as robosuite's environments see them, and the MJCF files robosuite reads for them.

robosuite lists each part's elements by name from the file it reads, and the environment looks every
listed name up in the compiled world. So the file robosuite reads for a gripper or base and the
assembly our robot builds must name every element alike: each part class has a robosuite variant (an
unregistered subclass) whose part spec gives unnamed geoms robosuite's names and, for a robot whose
spec says ``robosuite.actuation: torque``, drives with motors what robosuite's controllers drive. The
text is the lossless emission, kept in the cache across processes (:func:`.files.kept_file`):
every hard reset of an environment rebuilds every model, and the text of an unchanged part does not
change, so a warm ``robosuite.make`` neither builds nor writes any.
"""

from __future__ import annotations

import warnings
from collections.abc import Iterator
from typing import Any, TypeVar
from xml.sax.saxutils import escape, unescape

import mujoco

from assembler.cache.dependencies import asset_files
from assembler.errors import AssemblerWarning, SpecError
from assembler.mjcf.inertia_groups import weighed_by_other_groups
from assembler.models import GripperModel, ManipulatorModel, PartModel, RobotModel
from assembler.models.collision_colour import colour_collision_geoms
from assembler.robosuite.actuation import has_force_range, motorize, position_servos
from assembler.robosuite.arm_centers import add_arm_centers
from assembler.robosuite.conventions import DRIVEN_GROUPS, driven_actuators, robot_type_name
from assembler.robosuite.files import kept_file, written_file
from assembler.robosuite.geom_names import name_geoms_as_robosuite
from assembler.robosuite.grip_frames import add_grip_frames
from assembler.robosuite.lossless import lossless_xml
from assembler.spec.fieldpath import FieldPath

P = TypeVar("P", bound=PartModel)

ACTUATION = FieldPath(("robosuite", "actuation"))
JOINT_GROUPS = FieldPath(("joint_groups",))

ROBOSUITE_INERTIA_GROUPS = (0, 0)
"""The geom groups robosuite's world (``models/assets/base.xml``) counts in inferred inertias."""

NOTE = "<!-- assembler says: "
"""How a part file carries what its emission found to say (said again on every use of the file)."""

_DASH = {"-": "&#45;"}
"""A comment cannot hold ``--``: notes are written with every dash as a character reference."""

_variants: dict[type[Any], type[Any]] = {}


def robosuite_variant(cls: type[P]) -> type[P]:
    """``cls`` as robosuite sees it (made once per class, never registered)."""
    variant = _variants.get(cls)
    if variant is None:

        def part_mjspec(self: PartModel) -> mujoco.MjSpec:
            mjspec = name_geoms_as_robosuite(cls.part_mjspec(self))
            if self.spec.collision_colour != "robosuite":
                # robosuite's XML layer colours every collision geom itself when it reads a part: given
                # that colour here, what robosuite reads is what we give (docs/robosuite.md)
                colour_collision_geoms(mjspec, self.collision_rgba)
            if isinstance(self, ManipulatorModel):
                drive_as_declared(self, mjspec)
                add_arm_centers(self, mjspec)
            if isinstance(self, GripperModel):
                add_grip_frames(self, mjspec)
            return mjspec

        namespace = {
            "in_registry": False,
            "part_mjspec": part_mjspec,
            "__module__": __name__,
            "__doc__": f"{cls.__name__} as robosuite's environments see it.",
        }
        variant = type(cls.__name__, (cls,), namespace)
        _variants[cls] = variant
    return variant


def drive_as_declared(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> None:
    """Apply the spec's ``robosuite.actuation`` to ``mjspec``, the robot's part spec (unprefixed)."""
    undriven = undriven_joints(robot, mjspec)
    if undriven:
        raise SpecError(
            robot.spec_problem(
                JOINT_GROUPS,
                f"robosuite's controllers drive each joint of the groups they control with one actuator, "
                f"but {', '.join(undriven)} {'has' if len(undriven) == 1 else 'have'} none "
                "(a mimic follower?): declare an actuator for each, "
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


def undriven_joints(robot: ManipulatorModel, mjspec: mujoco.MjSpec) -> list[str]:
    """The robot's own joints (unprefixed) in groups robosuite's controllers drive that no actuator of
    ``mjspec`` (the robot's part spec) drives."""
    targets = {actuator.target for actuator in mjspec.actuators}
    driven = DRIVEN_GROUPS[robot_type_name(type(robot))]
    return [j for j in robot.joint_names if robot.group_of(j) in driven and j not in targets]


def part_file(part: PartModel) -> str:
    """The file robosuite reads for ``part`` alone (unprefixed: robosuite prefixes it)."""
    inputs = part.part_inputs()

    def emit() -> str:
        return lossless_xml(part.part_mjspec())

    if not inputs.spec_made:
        return written_file(emit())
    return kept_file(inputs, _files_read([part]), emit, lambda: _read_earlier([part]))


def assembly_file(robot: RobotModel) -> str:
    """The file robosuite reads for ``robot`` with its base and grippers (prefixed: our assembly);
    what robosuite's world will weigh differently is said on every use (the file carries it)."""
    inputs = robot.build_inputs()
    parts = [robot, *robot.models]

    def emit() -> str:
        mjspec = robot.build_mjspec()
        return _with_notes(lossless_xml(mjspec), _inertia_notes(robot, mjspec))

    path = (
        kept_file(inputs, _files_read(parts), emit, lambda: _read_earlier(parts))
        if inputs.cacheable
        else written_file(emit())
    )
    for note in _notes_of(path):
        warnings.warn(note, AssemblerWarning, stacklevel=2)
    return path


def _files_read(parts: list[PartModel]) -> Iterator[str]:
    """Every file the text of ``parts`` depends on: each part's MJCF and includes, and the asset files
    its text names (which must still be there). Lazy: a part's MJCF is read only when iterated."""
    for part in parts:
        yield from (path for path, _, _ in part.source.files)
        yield from asset_files(part.prepared_mjspec)


def _read_earlier(parts: list[PartModel]) -> dict[str, tuple[int, int]]:
    """Each part's MJCF and includes with their (size, mtime_ns) when the part read them."""
    return {path: (size, mtime) for part in parts for path, size, mtime in part.source.files}


def _inertia_notes(robot: RobotModel, mjspec: mujoco.MjSpec) -> list[str]:
    """Where robosuite's world will weigh a body of the assembly ``mjspec`` differently."""
    bodies = weighed_by_other_groups(mjspec, ROBOSUITE_INERTIA_GROUPS)
    if not bodies:
        return []
    shown = ", ".join(bodies[:4]) + (f" and {len(bodies) - 4} more" if len(bodies) > 4 else "")
    return [
        f"{type(robot).__name__}: robosuite's world counts only group-0 geoms in inferred masses "
        f'(<compiler inertiagrouprange="0 0">), so {shown} weigh less there than in the assembled '
        "model; give those bodies an <inertial> to make them agree"
    ]


def _with_notes(text: str, notes: list[str]) -> str:
    """``text`` with one leading comment line per note (XML readers skip comments)."""
    return "".join(f"{NOTE}{escape(note, _DASH)} -->\n" for note in notes) + text


def _notes_of(path: str) -> list[str]:
    """The notes at the head of a part file."""
    notes = []
    with open(path, encoding="utf-8") as file:
        for line in file:
            if not line.startswith(NOTE):
                break
            note = line.removeprefix(NOTE).removesuffix(" -->\n")
            notes.append(unescape(note, {v: k for k, v in _DASH.items()}))
    return notes
