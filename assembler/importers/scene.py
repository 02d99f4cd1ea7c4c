"""A task scene cut down to its robot, for ``assembler new``.

gymnasium-robotics' task files (``fetch/reach.xml``, ``hand/reach.xml``) hold a floor, a table,
targets and a mocap body welded to the hand around the robot's ``<include>``; a spec's file must
hold one robot under one root body. :func:`scene_cut` finds the robot (the child of ``<worldbody>``
whose subtree holds the most joints) and the ``mjcf_fixes`` deletions that leave it alone, as the
spec reads the file (the file itself is never changed): every other child of ``<worldbody>``, then
every element elsewhere that names something deleted (:mod:`assembler.importers.references`).

The file is read as MuJoCo reads it: included files are expanded where they stand, and the
fixes are written to select in the main file and its included files alike, as ``mjcf_fixes`` applies
them. A deletion selects its element by name, else by the fewest of its attributes that select it
alone, and never anything the robot keeps; an element no selection picks out so is named, not deleted.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from dataclasses import dataclass
from pathlib import Path

import mujoco

from assembler.importers.entries import Entry
from assembler.importers.references import Cut, dependent_cuts, label, selector
from assembler.importers.xml_files import XmlFiles
from assembler.spec.schema.fixes import MjcfFix

WORLD_CHILD_WHY: dict[str, str] = {
    "body": "a body of the task scene beside the robot (a table, a target, a floor marker)",
    "geom": "a geom fixed in the task scene's world (a floor, a wall), which would stay in every world the "
    "robot enters; drop this deletion if the geom is the robot's fixed base",
    "site": "a site of the task scene's world (a target marker)",
    "light": "the task scene's light; the worlds the robot enters light themselves",
    "camera": "the task scene's camera; the worlds the robot enters bring their own",
}
"""Why each kind of ``<worldbody>`` child beside the robot is deleted."""

MOCAP_WHY = (
    "a mocap body of the task, which moves the hand through a weld in gymnasium-robotics' tasks; "
    "robosuite's controllers drive the joints instead"
)


@dataclass(frozen=True)
class SceneCut:
    """What ``new`` deletes from a task scene, and what it could not."""

    robot: str
    """The root body kept: the child of ``<worldbody>`` whose subtree holds the most joints."""
    cuts: tuple[Cut, ...]
    unselectable: tuple[str, ...]
    """Elements beside the robot that no ``where:`` selects without selecting part of the robot."""
    twins: tuple[str, ...] = ()
    """Deleted bodies of ``<worldbody>`` that hold as many joints as the robot: a second robot or arm
    (gym-aloha's two ViperX arms stand on the world side by side)."""

    @property
    def fixes(self) -> list[MjcfFix]:
        return [MjcfFix(element=c.tag, where=c.where, delete=True, why=c.why) for c in self.cuts]


def _weights(model: mujoco.MjModel) -> dict[str, tuple[int, int]]:
    """Each child of the world by name -> the joints (free joints aside) and bodies its subtree holds."""
    roots = [b for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    free = int(mujoco.mjtJoint.mjJNT_FREE)

    def weight(root: int) -> tuple[int, int]:
        bodies = [b for b in range(1, model.nbody) if int(model.body_rootid[b]) == root]
        joints = sum(
            1
            for j in range(model.njnt)
            if int(model.jnt_bodyid[j]) in bodies and int(model.jnt_type[j]) != free
        )
        return joints, len(bodies)

    return {model.body(root).name: weight(root) for root in roots}


def _robot_body(model: mujoco.MjModel) -> str:
    """The world's child whose subtree holds the most joints (free joints aside), then most bodies."""
    weights = _weights(model)
    return max(weights, key=lambda name: weights[name]) if weights else ""


def _holds(element: ET.Element, body: str) -> bool:
    return any(item.tag == "body" and item.get("name") == body for item in element.iter())


def _world_children(files: XmlFiles) -> list[ET.Element]:
    return [child for world in files.sections("worldbody") for child in files.children(world)]


def scene_cut(path: Path, files: frozenset[Path], model: mujoco.MjModel) -> SceneCut | None:
    """The deletions that leave the robot of the MJCF at ``path`` alone (``files``: it and the files
    it includes, as read; ``model``: its compile), or None when it is no scene: one body in
    ``<worldbody>`` and no world geom (a light or a camera beside the robot stays, as in robosuite)."""
    xml = XmlFiles(path, files)
    robot = _robot_body(model)
    if not robot:  # an unnamed robot cannot be told from its scene; the spec's file check says so
        return None
    beside = [child for child in _world_children(xml) if not _holds(child, robot)]
    if not any(child.tag in ("body", "geom", "frame") for child in beside):
        return None
    cuts: list[Cut] = []
    unselectable: list[str] = []
    kept = [child for child in _world_children(xml) if _holds(child, robot)]
    for child in beside:
        where = selector(child, xml.every_root(), avoid=kept)
        shown = f"{label(child)} ({xml.where(child)})"
        if where is None:
            unselectable.append(shown)
            continue
        if any(cut.tag == child.tag and cut.where == where for cut in cuts):
            continue  # selected with an earlier one of the same attributes
        mocap = child.tag == "body" and child.get("mocap") == "true"
        why = MOCAP_WHY if mocap else WORLD_CHILD_WHY.get(child.tag, f"a <{child.tag}> of the task scene")
        cuts.append(Cut(child.tag, where, f"{shown}, beside the robot in <worldbody>", child, why))
    deleted = [cut.element for cut in cuts]
    more, lost = dependent_cuts(xml, deleted)
    weights = _weights(model)
    joints = weights[robot][0]
    twins = tuple(
        name for name, (count, _) in weights.items() if name != robot and joints and count == joints
    )
    return SceneCut(robot, tuple([*cuts, *more]), tuple([*unselectable, *lost]), twins)


def scene_entry(cut: SceneCut) -> Entry:
    """The ``mjcf_fixes`` field: each deletion with a comment saying what it removes and where (its
    ``why:`` says why), and the elements no deletion could select."""
    fixes = [{"element": c.tag, "where": c.where, "delete": True, "why": c.why} for c in cut.cuts]
    entry = Entry("mjcf_fixes", fixes, item_notes=[c.what for c in cut.cuts]).guess(
        f"this file is a task scene: the robot is {cut.robot}, the body of <worldbody> holding the most "
        "joints; the deletions below leave it alone as the spec reads the file (the file is not changed)"
    )
    if cut.twins:
        entry.decide(
            f"the file also holds {', '.join(cut.twins)}, of as many joints as {cut.robot} (a second arm, "
            f"a second robot), deleted below: this spec is {cut.robot} alone; a bimanual robot needs a file "
            "with both arms under one root body (arm_type: bimanual, docs/add-your-robot.md)"
        )
    if cut.unselectable:
        entry.decide(
            f"{', '.join(cut.unselectable)} should go too, but no where: selects them without selecting "
            "part of the robot: point the spec at a file of the robot alone"
        )
    return entry
