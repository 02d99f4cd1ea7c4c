"""A check that one of robosuite's own gripper or base objects names its elements as our spec of the
same name does.

A spec robot builds every part from our specs, but robosuite's ``Robot`` keeps the gripper and base
objects its factories made, and reads their name lists (joints and actuators in order: a gripper's
``format_action`` output i drives actuator i). When those objects are robosuite's own (not replaced
by ours), each listed name must exist in our assembly, in the same order where order matters; a
difference is an error, never a silent mismatch at the first step.
"""

from __future__ import annotations

from typing import Any

from assembler.errors import AssemblerError
from assembler.robosuite.part_classes import robosuite_class_of  # the classes import this module

ORDERED: tuple[str, ...] = ("joints", "actuators")
"""Lists whose order robosuite relies on."""

UNORDERED: tuple[str, ...] = ("bodies", "sites", "sensors", "contact_geoms", "visual_geoms")
"""Lists robosuite only looks names up in."""

_checked: set[tuple[type, type]] = set()


def check_same_names(theirs: Any, spec_class: type) -> None:
    """Raise unless robosuite's object ``theirs`` lists the names robosuite reads from the file of our
    ``spec_class`` (checked once per pair of classes)."""
    pair = (type(theirs), spec_class)
    if pair in _checked:
        return

    ours = robosuite_class_of(spec_class)(idn=theirs.idn)
    differences = []
    for field in ORDERED + UNORDERED:
        mine, yours = list(getattr(ours, field)), list(getattr(theirs, field))
        same = mine == yours if field in ORDERED else sorted(mine) == sorted(yours)
        if not same:
            only_ours = sorted(set(mine) - set(yours))
            only_theirs = sorted(set(yours) - set(mine))
            detail = f"only in the spec: {only_ours}; only in robosuite's: {only_theirs}"
            differences.append(f"{field} ({detail if only_ours or only_theirs else 'another order'})")
    if differences:
        name = type(theirs).__name__
        raise AssemblerError(
            f"robosuite's own {name} and the spec {name} name their elements differently: "
            f"{'; '.join(differences)}. Replace robosuite's with the spec "
            f"(assembler.robosuite.replace_robosuite(['{name}'])) or rename the spec"
        )
    _checked.add(pair)
