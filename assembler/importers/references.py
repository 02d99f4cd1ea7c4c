"""What else goes when ``new`` deletes part of a task scene: every element outside ``<worldbody>``
that names a deleted body, geom, site, joint, camera, tendon or actuator (a weld to a mocap body, a
contact exclusion, a tendon through a target site, a sensor on a deleted tendon, a keyframe whose
``qpos`` counts deleted joints), found until nothing more goes; and how one ``mjcf_fixes`` entry
selects an element (:func:`selector`).
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from assembler.importers.xml_files import XmlFiles

NAMED_KINDS: dict[str, str] = {
    "body": "body",
    "geom": "geom",
    "site": "site",
    "joint": "joint",
    "freejoint": "joint",
    "camera": "camera",
    "light": "light",
}
"""Elements inside ``<worldbody>`` whose name other elements refer to, and the kind of the name."""

REFERENCE_KINDS: dict[str, str] = {
    **dict.fromkeys(("body", "body1", "body2"), "body"),
    **dict.fromkeys(("site", "site1", "site2", "refsite", "sidesite", "cranksite", "slidersite"), "site"),
    **dict.fromkeys(("geom", "geom1", "geom2"), "geom"),
    **dict.fromkeys(("joint", "joint1", "joint2", "jointinparent"), "joint"),
    **dict.fromkeys(("tendon", "tendon1", "tendon2"), "tendon"),
    "actuator": "actuator",
    "camera": "camera",
}
"""Attributes that name another element (MuJoCo's XML reference), and the kind of element named."""

TYPED_REFERENCES = {"objname": "objtype", "refname": "reftype"}
"""Attributes naming an element whose kind another attribute gives (a frame sensor's object)."""

OBJECT_TYPES = {"xbody": "body"}

SECTIONS: dict[str, str | None] = {
    "equality": None,
    "contact": None,
    "tendon": "tendon",
    "actuator": "actuator",
    "sensor": "sensor",
}
"""Sections whose entries may name what ``<worldbody>`` holds, and the kind of name each entry has."""

KEY_NEEDS: dict[str, str] = {
    "qpos": "joint",
    "qvel": "joint",
    "ctrl": "actuator",
    "act": "actuator",
    "mpos": "mocap",
    "mquat": "mocap",
}
"""A keyframe's attributes and what deleting makes them the wrong length."""

KEY_WHAT = {"joint": "joints", "actuator": "actuators", "mocap": "mocap bodies"}


@dataclass(frozen=True)
class Cut:
    """One deletion ``new`` writes: the tag and attributes that select it, what it is and where
    (the comment above it), why (its ``why:``), and the element itself."""

    tag: str
    where: dict[str, str]
    what: str
    element: ET.Element
    why: str


def label(element: ET.Element) -> str:
    """``body robot0:mocap``, or ``unnamed geom`` for an element without a name."""
    name = element.get("name")
    return f"{element.tag} {name}" if name else f"unnamed {element.tag}"


def selector(
    element: ET.Element, roots: Iterable[ET.Element], avoid: Sequence[ET.Element]
) -> dict[str, str] | None:
    """The ``where:`` that selects ``element`` (``mjcf_fixes`` matches a tag and attribute values in
    every file alike): its name, else the fewest of its attributes (those naming other elements
    first) that select it alone, else all of them if what else they select is not inside ``avoid``
    (what is kept; the caller drops repeated selections); None when there is no such selection."""
    if element.get("name"):
        return {"name": element.get("name", "")}
    ordered = sorted(element.attrib, key=lambda name: name not in REFERENCE_KINDS)
    same_tag = [item for root in roots for item in root.iter(element.tag)]
    for count in range(1, len(ordered) + 1):
        where = {name: element.get(name, "") for name in ordered[:count]}
        if [item for item in same_tag if selects(item, where)] == [element]:
            return where
    kept = {id(item) for top in avoid for item in top.iter()}
    if not ordered or any(id(item) in kept and selects(item, element.attrib) for item in same_tag):
        return None
    return dict(element.attrib)


def selects(item: ET.Element, where: dict[str, str]) -> bool:
    """Whether ``where`` (a ``mjcf_fixes`` selection) selects ``item``."""
    return all(item.get(name) == value for name, value in where.items())


def _named(elements: Iterable[ET.Element]) -> dict[str, set[str]]:
    """Kind -> names of the named elements in the subtrees of ``elements``."""
    names: dict[str, set[str]] = {}
    for top in elements:
        for item in top.iter():
            kind = NAMED_KINDS.get(item.tag)
            if kind and item.get("name"):
                names.setdefault(kind, set()).add(item.get("name", ""))
            if item.tag == "body" and item.get("mocap") == "true":
                names.setdefault("mocap", set()).add(item.get("name", ""))
    return names


def _named_deleted(entry: ET.Element, deleted: dict[str, set[str]]) -> str | None:
    """The first deleted element ``entry`` (or anything inside it) names, as ``kind name``."""
    for item in entry.iter():
        for attribute, value in item.attrib.items():
            kind = REFERENCE_KINDS.get(attribute)
            if attribute in TYPED_REFERENCES:
                typed = item.get(TYPED_REFERENCES[attribute], "")
                kind = OBJECT_TYPES.get(typed, typed)
            if kind and value in deleted.get(kind, ()):
                return f"{kind} {value}"
    return None


def _stale_key(key: ET.Element, deleted: dict[str, set[str]]) -> str | None:
    for attribute, needs in KEY_NEEDS.items():
        if key.get(attribute) and deleted.get(needs):
            return f"its {attribute} has values for the {KEY_WHAT[needs]} deleted above"
    return None


def dependent_cuts(xml: XmlFiles, deleted: Sequence[ET.Element]) -> tuple[list[Cut], list[str]]:
    """The deletions that follow from deleting ``deleted`` (until none follows), and the elements that
    should go but that no selection picks out without touching an entry that stays."""
    names = _named(deleted)
    entries = [
        (section, kind, entry)
        for section, kind in SECTIONS.items()
        for s in xml.sections(section)
        for entry in xml.children(s)
    ]
    cuts: list[Cut] = []
    lost: list[str] = []
    done: set[int] = set()
    roots = xml.every_root()
    changed = True
    while changed:
        changed = False
        for section, kind, entry in entries:
            named = None if id(entry) in done else _named_deleted(entry, names)
            if named is None:
                continue
            done.add(id(entry))
            changed = True
            if kind and entry.get("name"):
                names.setdefault(kind, set()).add(entry.get("name", ""))
            shown = f"{label(entry)} in <{section}> ({xml.where(entry)})"
            where = selector(
                entry, roots, avoid=[e for _, _, e in entries if _named_deleted(e, names) is None]
            )
            if where is None:
                lost.append(shown)
                continue
            if any(cut.tag == entry.tag and cut.where == where for cut in cuts):
                continue  # selected with an earlier one of the same attributes
            cuts.append(Cut(entry.tag, where, shown, entry, f"it names {named}, deleted above"))
    for keyframe in xml.sections("keyframe"):
        for key in xml.children(keyframe):
            stale = _stale_key(key, names)
            where = selector(key, roots, avoid=[]) if stale else None
            if stale and where is None:
                lost.append(f"{label(key)} ({xml.where(key)})")
            elif stale and where is not None:
                cuts.append(Cut(key.tag, where, f"{label(key)} ({xml.where(key)})", key, stale))
    return cuts, lost
