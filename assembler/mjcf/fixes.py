"""Apply a spec's declared MJCF repairs (``mjcf_fixes``) to the parsed XML before MuJoCo reads it."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Sequence

from assembler.spec.schema.fixes import MjcfFix


def apply_fixes(root: ET.Element, fixes: Sequence[MjcfFix]) -> list[str]:
    """Repair ``root`` in place; return one line per fix that changed nothing (a stale fix, which
    the caller reports: a repair that no longer applies should be deleted, not kept silently)."""
    stale = []
    for fix in fixes:
        elements = [root] if root.tag == fix.element else list(root.iter(fix.element))
        if fix.keep_first_of_repeated_names:
            changed = _drop_repeated_names(root, fix.element)
        elif fix.remove:
            removed = [element.attrib.pop(name, None) for element in elements for name in fix.remove]
            changed = sum(value is not None for value in removed)
        else:
            if not elements:
                elements = [ET.Element(fix.element)]
                root.insert(0, elements[0])  # sections such as <compiler> come before what they govern
            changed = sum(any(element.get(k) != v for k, v in fix.set.items()) for element in elements)
            for element in elements:
                element.attrib.update(fix.set)
        if not changed:
            stale.append(f"mjcf_fixes on <{fix.element}> changed nothing; delete it if the file is fixed")
    return stale


def _drop_repeated_names(root: ET.Element, tag: str) -> int:
    seen: set[str] = set()
    dropped = 0
    for parent in list(root.iter()):
        for child in list(parent):
            name = child.get("name")
            if child.tag != tag or name is None:
                continue
            if name in seen:
                parent.remove(child)
                dropped += 1
            seen.add(name)
    return dropped
