"""The file's own actuators made ones robosuite can drive, through ``mjcf_fixes`` (the file is not
changed): robosuite and a gripper's ``actions:`` find an actuator by its name, so an unnamed actuator
on a joint (gym-aloha's ViperX servos, metaworld's Sawyer claws) takes its joint's name; and
``robosuite.actuation: torque`` makes each of the arm's position servos a motor whose ctrlrange is the
servo's forcerange, so an unnamed arm servo without one (gym-aloha's wrist servos) is given the most it
pushes at rest, ``kp`` times the widest error its control and joint ranges allow: MuJoCo drives it as
the file makes it. A named servo without forcerange is left as the file has it, for the user to bound
(``new`` says so in ``robosuite:``): a file that names its actuators is written for other controllers,
one that leaves them unnamed only for its own task's, which drives them by index.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Collection, Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco

from assembler.importers.entries import Entry
from assembler.importers.entries import short as _short
from assembler.importers.physics import round_up
from assembler.importers.reading import ModelFile
from assembler.importers.references import label, selector, selects
from assembler.importers.xml_files import XmlFiles
from assembler.mjcf.fixes import apply_fixes
from assembler.robosuite.conventions import has_force_range, is_bridge_servo
from assembler.spec.schema.fixes import MjcfFix

JOINT_TRANSMISSION = int(mujoco.mjtTrn.mjTRN_JOINT)

NAMED_WHY = "robosuite and a gripper's actions: find an actuator by its name, and this one has none"
BOUNDED_WHY = (
    "robosuite.actuation: torque makes this servo a motor whose ctrlrange is its forcerange, and it has "
    "none: the most it pushes at rest, kp times the widest error its ctrlrange and joint range allow, "
    "so MuJoCo drives it as the file makes it"
)


@dataclass(frozen=True)
class ActuatorFix:
    """One ``mjcf_fixes`` entry on an unnamed actuator of the file: its name, and its forcerange if it
    needs one."""

    fix: MjcfFix
    what: str
    """The comment above it: the actuator and where it is written."""
    joint: str
    """The joint it drives (a jaw's spec keeps the fixes of the jaw's actuators)."""
    named: str
    """The name it is given."""
    bound: float | None
    """The force limit it is given, if it had none."""


def actuator_fixes(file: ModelFile, fixes: Sequence[MjcfFix], arm: Collection[str]) -> list[ActuatorFix]:
    """The fixes naming ``file``'s unnamed actuators on joints and bounding those of them that are
    position servos without forcerange on the joints in ``arm``; ``file`` is the MJCF as read with
    ``fixes``, which the selections are made after (``mjcf_fixes`` applies its entries in order)."""
    xml = XmlFiles(file.path, frozenset(Path(p) for p, _, _ in file.source.files))
    roots = xml.every_root()
    apply_fixes(roots, fixes)  # the XML as MuJoCo compiled it: the model's actuators, in its order
    model = file.model
    elements = [entry for section in xml.sections("actuator") for entry in xml.children(section)]
    if len(elements) != model.nu:  # an actuator section this reading does not follow: nothing guessed
        return []
    taken = {model.actuator(a).name for a in range(model.nu)}
    found = []
    for actuator, element in enumerate(elements):
        if int(model.actuator_trntype[actuator]) != JOINT_TRANSMISSION:
            continue
        joint = model.joint(int(model.actuator_trnid[actuator, 0])).name
        if element.get("joint") != joint:  # not the element this actuator was read from
            return []
        named = None if element.get("name") else _free_name(joint, element.tag, taken)
        if named is None:
            continue
        bound = _reach(model, actuator) if joint in arm and not has_force_range(model, actuator) else None
        where = _only(element, roots)
        if where is None:
            continue
        taken.add(named)
        settings = {"name": named}
        if bound is not None:
            settings |= {"forcerange": f"{-bound:g} {bound:g}", "forcelimited": "true"}
        why = NAMED_WHY if bound is None else f"{NAMED_WHY}; {BOUNDED_WHY}"
        fix = MjcfFix(element=element.tag, where=where, set=settings, why=why)
        what = f"{label(element)} in <actuator> ({xml.where(element)})"
        found.append(ActuatorFix(fix, what, joint, named, bound))
    return found


def _free_name(joint: str, tag: str, taken: set[str]) -> str | None:
    """The joint's name, else the joint's and the tag's, whichever no actuator has; None if both are taken."""
    return next((name for name in (joint, f"{joint}_{tag}") if name not in taken), None)


def _reach(model: mujoco.MjModel, actuator: int) -> float | None:
    """The largest force the position servo ``actuator`` exerts at rest: kp times the widest distance
    between a control in its ctrlrange and its joint's position in the joint's range (times the gear),
    rounded up; None for another kind of actuator or when either range is open."""
    joint = int(model.actuator_trnid[actuator, 0])
    if not is_bridge_servo(model, actuator):
        return None
    if not model.actuator_ctrllimited[actuator] or not model.jnt_limited[joint]:
        return None
    gear, kp = float(model.actuator_gear[actuator, 0]), float(model.actuator_gainprm[actuator, 0])
    controls = model.actuator_ctrlrange[actuator]
    lengths = gear * model.jnt_range[joint]
    widest = max(abs(float(c) - float(q)) for c in controls for q in lengths)
    return round_up(kp * widest) if kp * widest > 0 else None


def _only(element: ET.Element, roots: Sequence[ET.Element]) -> dict[str, str] | None:
    """The ``where:`` that selects ``element`` and nothing else, or None."""
    where = selector(element, roots, avoid=[])
    if where is None:
        return None
    same = [item for root in roots for item in root.iter(element.tag)]
    selected = [item for item in same if selects(item, where)]
    return where if selected == [element] else None


def fixes_entry(scene: Entry | None, found: Sequence[ActuatorFix]) -> Entry | None:
    """The ``mjcf_fixes`` field: the scene's deletions (``scene``, if any) and then ``found``, each with
    a comment saying what it changes and where; None when there is neither."""
    if not found:
        return scene
    entry = scene or Entry("mjcf_fixes", [])
    entry.value = [*entry.value, *(_as_item(each.fix) for each in found)]
    entry.item_notes = [*entry.item_notes, *(each.what for each in found)]
    entry.guess(
        f"{_short([each.named for each in found])}: the file's unnamed actuators, named after their "
        "joints below"
    )
    bounded = [each.named for each in found if each.bound]
    if bounded:
        entry.decide(
            f"{_short(bounded)}: the forcerange below is the most each servo pushes, not its motor's torque "
            "limit: set each joint's real limit"
        )
    return entry


def _as_item(fix: MjcfFix) -> dict[str, object]:
    return {"element": fix.element, "where": fix.where, "set": fix.set, "why": fix.why}


__all__ = ["ActuatorFix", "actuator_fixes", "fixes_entry"]
