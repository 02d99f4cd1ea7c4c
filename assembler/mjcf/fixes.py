"""Apply a spec's declared MJCF repairs (``mjcf_fixes``) to the parsed XML before MuJoCo reads it.

A repair applies to the file and every file it ``<include>``s alike (dm-control's robots keep their
defaults and materials in an included ``common.xml``): the XML trees are repaired together, and a
repair that changed nothing in any of them is reported as stale.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator, Sequence

from assembler.spec.schema.fixes import MjcfFix


def apply_fixes(roots: Sequence[ET.Element], fixes: Sequence[MjcfFix]) -> list[str]:
    """Repair the trees in place (``roots[0]`` the main file's, then its included files'); return one
    line per fix that changed nothing (a stale fix, which the caller reports: a repair that no
    longer applies should be deleted, not kept silently)."""
    stale = []
    for fix in fixes:
        if fix.keep_first_of_repeated_names:
            changed = _drop_repeated_names(roots, fix)
        elif fix.delete:
            changed = _delete(roots, fix)
        elif fix.remove:
            elements = [element for _, element in _matching(roots, fix)]
            removed = [element.attrib.pop(name, None) for element in elements for name in fix.remove]
            changed = sum(value is not None for value in removed)
        else:
            changed = _set(roots, fix)
        if not changed:
            stale.append(f"mjcf_fixes on <{fix.element}> changed nothing; delete it if the file is fixed")
    return stale


def _matching(roots: Sequence[ET.Element], fix: MjcfFix) -> Iterator[tuple[ET.Element, ET.Element]]:
    """(parent, element) for every element the fix applies to: its tag, and the attribute values of
    its ``where``; a root element itself has itself as parent."""
    for root in roots:
        if root.tag == fix.element and _selected(root, fix):
            yield root, root
        for parent in root.iter():
            for child in parent:
                if child.tag == fix.element and _selected(child, fix):
                    yield parent, child


def _selected(element: ET.Element, fix: MjcfFix) -> bool:
    return all(element.get(name) == value for name, value in fix.where.items())


def _set(roots: Sequence[ET.Element], fix: MjcfFix) -> int:
    elements = [element for _, element in _matching(roots, fix)]
    if not elements and not fix.where:
        elements = [ET.Element(fix.element)]
        roots[0].insert(0, elements[0])  # sections such as <compiler> come before what they govern
    changed = sum(any(element.get(k) != v for k, v in fix.set.items()) for element in elements)
    for element in elements:
        element.attrib.update(fix.set)
    return changed


def _delete(roots: Sequence[ET.Element], fix: MjcfFix) -> int:
    found = [(parent, element) for parent, element in _matching(roots, fix) if parent is not element]
    for parent, element in found:
        parent.remove(element)
    return len(found)


def _drop_repeated_names(roots: Sequence[ET.Element], fix: MjcfFix) -> int:
    seen: set[str] = set()
    dropped = 0
    for parent, child in list(_matching(roots, fix)):
        name = child.get("name")
        if parent is child or name is None:
            continue
        if name in seen:
            parent.remove(child)
            dropped += 1
        seen.add(name)
    return dropped
