"""Where a joint parameter's final value came from, as data; rendered to text only for display.

``assembler inspect`` prints it, the cache and the checks read its fields; nothing parses the
text back.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Literal

Origin = Literal["mjcf", "rule", "override", "added", "motor", "api"]
"""The MJCF file itself, a spec default rule, a spec ``joints:`` override, a joint the spec adds,
the motor a spec ``motors:`` entry puts on the joint, or a ``set_joint_attribute`` call."""

HowAuthored = Literal["literal", "main default", "class", "urdf <dynamics>"]
"""How the model file sets a value: on the element, in its main ``<default>``, through a default class
(explicit, nested or an ancestor's ``childclass``), or, for a URDF, in a joint's ``<dynamics>``."""


@dataclass(frozen=True)
class Provenance:
    """The source of one joint parameter."""

    origin: Origin
    how: HowAuthored | None = None
    """For ``mjcf``: how the file sets it."""

    class_name: str = ""
    """For ``mjcf`` through a class: the class's name."""

    rule: str = ""
    """For ``rule``: the rule as written, e.g. ``5/(i+1)``, ``0.1`` or ``(list)``."""

    index: int | None = None
    """For ``override``, ``added`` and ``motor``: the index of the spec entry (``joints[i]``,
    ``added_joints[i]``, ``motors[i]``)."""

    motor: str = ""
    """For ``motor``: the motor spec's name."""

    formula: str = ""
    """For ``motor``: how the value follows from the motor spec, e.g. ``rotor_inertia × gear_ratio²``."""

    numbers: str = ""
    """For ``motor``: the formula with the motor spec's numbers, e.g. ``1.12e-05 kg·m² × 29.5²``."""

    inverse_index: float | None = None
    """For the inverse-index rule ``scale/(i+1)``: its scale."""

    @property
    def from_file(self) -> bool:
        """True when the MJCF file sets the value."""
        return self.origin == "mjcf"

    def __str__(self) -> str:
        if self.how == "urdf <dynamics>":
            return "urdf <dynamics>"
        if self.origin == "mjcf":
            detail = f"class '{self.class_name}'" if self.how == "class" else str(self.how)
            return f"mjcf ({detail})"
        if self.origin == "rule":
            return f"rule {self.rule}"
        if self.origin == "override":
            return f"spec joints[{self.index}]"
        if self.origin == "added":
            return f"spec added_joints[{self.index}]"
        if self.origin == "motor":
            return f"spec motors[{self.index}] {self.motor}: {self.formula}"
        return "set_joint_attribute"


API = Provenance("api")
"""A value set through ``set_joint_attribute``."""
