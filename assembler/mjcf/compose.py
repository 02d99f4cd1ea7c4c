"""Composing parts into one assembly, and what ``MjSpec.attach`` misses on older MuJoCo releases.

Compose parts into one assembly: mount, mobile, legged and null bases; grippers on hands.

Every part is attached with ``MjSpec.attach`` under its own non-empty prefix, so names, default
classes and assets never collide (an empty prefix duplicates default classes: MuJoCo #2707). Bodies
are selected by name, never by position. Where robosuite re-parents the arm under a base's
support body, we attach the robot's own root there, renamed ``manipulator_mount`` (and so
prefixed ``robot{idn}_manipulator_mount``); a new outer body keeps the robot root's name and pose.

What ``MjSpec.attach`` misses on the older MuJoCo releases we support, put right or refused.

Each rule names the release that fixed MuJoCo's behaviour; on that release and later it does
nothing. Before 3.16, attaching a part with a prefix left its tendons' material references and its
skins' names unprefixed (the compile then fails, or names collide between parts). Before 3.17, the
bones a skin *file* names are not prefixed either, and the file cannot be rewritten: such a part is
refused when it is read, with what to do. On 3.9 (4.0 is right; the releases between are not tested),
a part whose defaults give sites a material (dm-control's Kinova ``common.xml``:
``<default><site material="red"/>``) cannot be compiled once attached with a prefix ("material 'red'
not found in site 0"), whatever its sites say: the part is re-read without those default materials,
its sites keeping the materials the defaults gave them.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import mujoco
from numpy.typing import ArrayLike

from assembler.errors import MjcfError, summarize_names
from assembler.files.paths import display_path
from assembler.mjcf.emit import to_xml
from assembler.mjcf.installed_mujoco import mujoco_at_least
from assembler.mjcf.joints import FREE, remove_free_joints

MANIPULATOR_MOUNT = "manipulator_mount"

USER_COLUMNS: tuple[str, ...] = (
    "nuser_body",
    "nuser_jnt",
    "nuser_geom",
    "nuser_site",
    "nuser_cam",
    "nuser_tendon",
    "nuser_actuator",
    "nuser_sensor",
)
"""``<size>`` fields that say how many user-data columns an element kind has (-1: as many as used)."""


def attach(
    assembly: mujoco.MjSpec,
    part: mujoco.MjSpec,
    frame: mujoco.MjsFrame,
    prefix: str,
) -> None:
    """Attach a whole part under ``frame`` with ``prefix``; the assembly's model-wide options win.

    robosuite never merges a part's <option>/<visual> either. The part takes the assembly's values
    before attaching, so MuJoCo sees no conflict: otherwise it warns at compile time and appends
    the warning to MUJOCO_LOG.TXT in the user's working directory. User-data columns are the
    exception: MuJoCo's attach keeps the assembly's count (-1, as many as used) and so cuts a part's
    declared columns (the Shadow hand's 16 ``nuser_actuator``), so the assembly takes the larger count.
    The part's memory sizes (``njmax``, ``nconmax``, ``memory``) are not carried: MuJoCo says so.
    """
    part.option = assembly.option
    part.visual = assembly.visual
    for field in USER_COLUMNS:
        columns = max(getattr(assembly, field), getattr(part, field))
        setattr(assembly, field, columns)
        if getattr(part, field) != -1:
            setattr(part, field, columns)  # the same count on both sides: no conflict to warn of
    prefix_what_attach_misses(part, prefix)
    assembly.attach(part, frame=frame, prefix=prefix)


def find_body(assembly: mujoco.MjSpec, name: str, what: str) -> mujoco.MjsBody:
    """The body called ``name``; a clear error listing the bodies when it does not exist."""
    body = assembly.body(name)
    if body is None:
        names = [b.name for b in assembly.bodies[1:] if b.name]
        raise MjcfError(f"{what}: no body named '{name}'. Bodies: {summarize_names(names)}")
    return body


def new_assembly(globals_xml: str) -> mujoco.MjSpec:
    """An empty assembly whose model-wide sections (option, compiler, ...) are the given ones."""
    return mujoco.MjSpec.from_string(globals_xml)


def attach_at_world(assembly: mujoco.MjSpec, part: mujoco.MjSpec, prefix: str) -> None:
    """Attach a part at the world origin."""
    attach(assembly, part, assembly.worldbody.add_frame(), prefix)


def attach_mount(
    assembly: mujoco.MjSpec, robot_root: str, mount: mujoco.MjSpec, prefix: str, offset: ArrayLike
) -> None:
    """A fixed mount becomes the last child of the robot's root body; its root is moved to ``offset``
    (robosuite overwrites the mount root's own position the same way)."""
    root = find_body(assembly, robot_root, "mount")
    mount.worldbody.first_body().pos = offset
    attach(assembly, mount, root.add_frame(), prefix)


def attach_robot_on_support(
    assembly: mujoco.MjSpec,
    robot: mujoco.MjSpec,
    robot_prefix: str,
    base: mujoco.MjSpec,
    base_prefix: str,
    support_body: str,
    offset: ArrayLike,
    legged: bool,
) -> None:
    """A mobile or legged base between the robot's root and the rest of the robot.

    The result is ``<robot root>`` (pose of the robot's root; for a legged base, its free joint and
    the robot root's inertia) -> base root, moved to ``offset`` -> ... -> ``support_body`` ->
    ``<robot prefix>manipulator_mount`` (the robot's former root: its children, geoms, sites and
    cameras; no free joint, as in robosuite) -> the arm. On a mobile base the mount's mass comes from
    its geoms, as in robosuite; on a legged base it has none (robosuite keeps the root's geoms and
    inertial on the outer body there, which carries the root's inertia here).
    """
    root = robot.worldbody.first_body()
    outer = assembly.worldbody.add_body(name=robot_prefix + root.name, pos=root.pos, quat=root.quat)
    if legged:
        outer.mass, outer.ipos, outer.iquat = root.mass, root.ipos, root.iquat
        outer.inertia, outer.fullinertia = root.inertia, root.fullinertia
        outer.explicitinertial = root.explicitinertial
        base_root = base.worldbody.first_body()
        if any(j.type == FREE for j in base_root.joints):
            remove_free_joints(base)
            outer.add_freejoint()
    base.worldbody.first_body().pos = offset  # replaces the base root's own position
    earlier = len(assembly.actuators)  # a scene's assembly already holds other robots' actuators
    attach(assembly, base, outer.add_frame(), base_prefix)
    base_actuators = [actuator.name for actuator in assembly.actuators[earlier:]]
    support = find_body(assembly, base_prefix + support_body, "base support body")

    move_world_elements(robot, assembly, robot_prefix)
    for exclude in robot.excludes:  # they name bodies by text: follow the root to its new name
        if exclude.bodyname1 == root.name:
            exclude.bodyname1 = MANIPULATOR_MOUNT
        if exclude.bodyname2 == root.name:
            exclude.bodyname2 = MANIPULATOR_MOUNT
    root.name = MANIPULATOR_MOUNT
    root.pos = [0.0, 0.0, 0.0]
    root.quat = [1.0, 0.0, 0.0, 0.0]
    drop_inertial(root, keep_zero=legged)
    for joint in list(root.joints):
        if joint.type == FREE:
            robot.delete(joint)
    attach(assembly, robot, support.add_frame(), robot_prefix)
    # robosuite appends a base's actuators after the robot's: keep that control order.
    move_actuators_last(assembly, base_actuators)


def drop_inertial(body: mujoco.MjsBody, keep_zero: bool) -> None:
    """Remove the body's ``<inertial>``: MuJoCo then infers it from the body's geoms, as robosuite's
    add_mobile_base does when it leaves out the root's ``<inertial>`` (robot_model.py:209-217). With
    ``keep_zero`` the body gets an explicit inertial of zero mass instead."""
    body.mass = 0.0
    body.inertia = [0.0, 0.0, 0.0]
    body.iquat = [1.0, 0.0, 0.0, 0.0]
    body.fullinertia = [float("nan"), 0.0, 0.0, 0.0, 0.0, 0.0]
    body.explicitinertial = keep_zero
    # MjSpec marks a body without <inertial> by an undefined (NaN) inertial position.
    body.ipos = [0.0, 0.0, 0.0] if keep_zero else [float("nan"), 0.0, 0.0]


_NOT_COPIED = frozenset(
    {"id", "signature", "info", "plugin", "classname", "name", "compiler", "parent", "frame"}
)
"""Element properties that identify it, tie it to its spec, or cannot be set; the rest are copied."""


def copy_properties(source: Any, target: Any) -> None:
    """Copy every settable property of one MjSpec element onto a new element of the same kind
    (MjSpec has no clone or reorder operation)."""
    for field in dir(source):
        if not field.startswith("_") and field not in _NOT_COPIED and not callable(getattr(source, field)):
            setattr(target, field, getattr(source, field))


def move_actuators_last(assembly: mujoco.MjSpec, names: Sequence[str]) -> None:
    """Move the named actuators, in order, to the end of the actuator list."""
    for name in names:
        old = next(a for a in assembly.actuators if a.name == name)  # not assembly.actuator(): see
        new = assembly.add_actuator()  # mjcf.actuators.find_actuator (MuJoCo 3.9 misses added ones)
        copy_properties(old, new)
        assembly.delete(old)
        new.name = name


_PREFIXED_REFERENCES = ("material", "meshname", "hfieldname", "targetbody")
"""Fields of a geom, site, camera or light that name another element of the same part."""


def move_world_elements(part: mujoco.MjSpec, assembly: mujoco.MjSpec, prefix: str) -> None:
    """Keep a part's world-level geoms, sites, cameras and lights in the world (as robosuite does)
    when its root body is attached somewhere else, e.g. under a mobile base's support body."""
    world = assembly.worldbody
    kinds = [
        (part.worldbody.geoms, world.add_geom),
        (part.worldbody.sites, world.add_site),
        (part.worldbody.cameras, world.add_camera),
        (part.worldbody.lights, world.add_light),
    ]
    for elements, add in kinds:
        for element in list(elements):
            copy = add()
            copy_properties(element, copy)
            copy.name = prefix + element.name if element.name else ""
            for reference in _PREFIXED_REFERENCES:  # names of the part's own elements get its prefix
                if getattr(element, reference, ""):
                    setattr(copy, reference, prefix + getattr(element, reference))
            part.delete(element)


STAND_IN_MASS = 1.0
"""kg: the load a mobile or legged base carries on its support when compiled without a robot."""


def add_stand_in_load(assembly: mujoco.MjSpec, support_body: str) -> None:
    """A small mass on the support body, standing in for the robot a mobile or legged base carries
    (robosuite's NullMobileBase has no mass of its own on its moving support)."""
    support = find_body(assembly, support_body, "base support body")
    support.add_body(name=support_body + "_stand_in_load", mass=STAND_IN_MASS, inertia=[0.01, 0.01, 0.01])


def add_sites_at_world(assembly: mujoco.MjSpec, part: mujoco.MjSpec, prefix: str) -> None:
    """A null base contributes only its sites, placed in the world frame (robosuite's add_null_base)."""
    for site in part.sites:
        assembly.worldbody.add_site(
            name=prefix + site.name,
            type=site.type,
            size=site.size,
            pos=site.pos,
            quat=site.quat,
            rgba=site.rgba,
            group=site.group,
        )


def attach_gripper(
    assembly: mujoco.MjSpec,
    hand_body: str,
    gripper: mujoco.MjSpec,
    prefix: str,
    pos: Sequence[float] | None,
    quat: Sequence[float] | None,
) -> None:
    """Attach a gripper as the last child of the hand body, with the robot's mount pose if given."""
    hand = find_body(assembly, hand_body, "end-effector body")
    place_root(gripper, pos, quat)
    attach(assembly, gripper, hand.add_frame(), prefix)


def place_root(part: mujoco.MjSpec, pos: Sequence[float] | None, quat: Sequence[float] | None) -> None:
    """Give ``part``'s root body this position and orientation (None: keep the file's). The
    orientation replaces one the file gives in any form (euler, axisangle, ...): MuJoCo would
    otherwise compile the file's form and ignore the quaternion."""
    root = part.worldbody.first_body()
    if pos is not None:
        root.pos = list(pos)
    if quat is not None:
        root.quat = list(quat)
        root.alt.type = mujoco.mjtOrientation.mjORIENTATION_QUAT


PREFIXES_TENDON_MATERIALS_AND_SKINS = (3, 16)
PREFIXES_SKIN_FILE_BONES = (3, 17)
ATTACHES_DEFAULT_SITE_MATERIALS = (4, 0)


def refuse_unattachable(part: mujoco.MjSpec, shown: str) -> None:
    """A part MuJoCo's attach would break on this release: a skin whose bones come from its file."""
    if mujoco_at_least(*PREFIXES_SKIN_FILE_BONES):
        return
    for skin in part.skins:
        if skin.file:
            release = ".".join(map(str, PREFIXES_SKIN_FILE_BONES))
            raise MjcfError(
                f"{shown}: skin '{skin.name}' reads its bones from {display_path(skin.file)}, which MuJoCo "
                f"{mujoco.__version__} cannot rename when it attaches the part (fixed in {release}): "
                f"write the skin's vertices and bones in the MJCF, or install mujoco>={release}"
            )


def prefix_what_attach_misses(part: mujoco.MjSpec, prefix: str) -> None:
    """Give ``part``'s tendon materials and skin names the prefix before it is attached with it, on
    releases whose attach leaves them as they are (an attached spec's elements cannot be edited
    through the assembly afterwards: the attach is by reference)."""
    if mujoco_at_least(*PREFIXES_TENDON_MATERIALS_AND_SKINS):
        return
    for tendon in part.tendons:
        if tendon.material:
            tendon.material = prefix + tendon.material
    for skin in part.skins:
        if skin.name:
            skin.name = prefix + skin.name


def settle_default_site_materials(part: mujoco.MjSpec) -> mujoco.MjSpec:
    """``part``, or on releases whose attach breaks on a default site material, the same model re-read
    from MuJoCo's own XML of it with the defaults' site materials moved onto the sites (which already
    hold them). Only a re-read clears what the defaults left behind: editing the defaults in place or
    copying the spec does not. Asset paths must already be absolute."""
    if mujoco_at_least(*ATTACHES_DEFAULT_SITE_MATERIALS):
        return part
    defaults = [part.default, *(site.classname for site in part.sites)]
    with_material = [default for default in defaults if default.site.material]
    if not with_material:
        return part
    for default in with_material:
        default.site.material = ""
    return mujoco.MjSpec.from_string(to_xml(part))  # every digit: MuJoCo's writer keeps six
