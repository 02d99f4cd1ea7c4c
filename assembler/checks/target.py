"""What the checks look at: one compiled assembly posed at its home keyframe, and the parts behind it.

Every element of the assembly carries its part's prefix (``robot0_``, ``gripper0_right_``, ...), so
a finding about an element can be traced back to the part, its spec field or its MJCF line.
"""

from __future__ import annotations

import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import mujoco

from assembler.compiler.keyframe import HOME_KEY
from assembler.errors import Location
from assembler.files.paths import display_path
from assembler.models import GripperModel, PartModel, RobotModel
from assembler.spec.fieldpath import FieldPath

ACTUATOR_TAGS: tuple[str, ...] = (
    "general",
    "motor",
    "position",
    "velocity",
    "intvelocity",
    "damper",
    "cylinder",
    "muscle",
    "adhesion",
)
"""MJCF elements that define an actuator."""


@dataclass(frozen=True)
class LintTarget:
    """A compiled assembly at its ``home`` keyframe (after ``mj_forward``) and the parts it was built from."""

    name: str
    """What the user asked to lint, e.g. ``Sparrow7``."""

    model: mujoco.MjModel
    data: mujoco.MjData
    parts: tuple[PartModel, ...]
    """The robot first, then its base and grippers (or a single base or gripper)."""

    hangs_on_moving_body: bool = False
    """A gripper linted alone: welded to the world here, it will hang off a moving hand in use."""

    def element_name(self, kind: mujoco.mjtObj, index: int) -> str:
        """An element's name, or e.g. ``geom #3`` when it has none."""
        name = mujoco.mj_id2name(self.model, kind, index)
        return name or f"{kind.name.removeprefix('mjOBJ_').lower()} #{index}"

    def part_of(self, name: str) -> PartModel | None:
        """The part whose prefix the (prefixed) element ``name`` carries, the longest prefix winning."""
        owners = [p for p in self.parts if name.startswith(p.naming_prefix)]
        return max(owners, key=lambda p: len(p.naming_prefix), default=None)

    def spec_location(self, part: PartModel | None, path: FieldPath) -> Location | None:
        """Where a field of ``part``'s spec is written (or the nearest enclosing field)."""
        if part is None or part.loaded is None:
            return None
        return part.loaded.location(path)

    def element_location(self, tags: Sequence[str], name: str) -> Location | None:
        """The line of the MJCF element ``name`` (prefixed), else the part's model file spec field."""
        part = self.part_of(name)
        if part is None:
            return None
        local = name[len(part.naming_prefix) :]
        return mjcf_element_location(part.source.path, tags, local) or self.spec_location(
            part, FieldPath((part.spec.source_field,))
        )


def mjcf_element_location(path: str | Path, tags: Sequence[str], name: str) -> Location | None:
    """Where ``<tag ... name="name"`` starts in an MJCF file (first match), by a plain text search."""
    try:
        text = Path(path).read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return None
    alternatives = "|".join(re.escape(tag) for tag in tags)
    pattern = rf"<(?:{alternatives})\b[^>]*?\bname\s*=\s*([\"']){re.escape(name)}\1"
    match = re.search(pattern, text)
    if match is None:
        return None
    line_start = text.rfind("\n", 0, match.start()) + 1
    return Location(
        display_path(str(path)), text.count("\n", 0, match.start()) + 1, match.start() - line_start + 1
    )


def _posed(
    name: str, model: mujoco.MjModel, parts: tuple[PartModel, ...], hangs_on_moving_body: bool = False
) -> LintTarget:
    data = mujoco.MjData(model)
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    if key >= 0:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_forward(model, data)
    return LintTarget(name, model, data, parts, hangs_on_moving_body)


def robot_target(robot: RobotModel, name: str | None = None, cache: bool = True) -> LintTarget:
    """A robot with its base and grippers, compiled and posed at ``home``."""
    return _posed(name or type(robot).__name__, robot.get_model(cache=cache), (robot, *robot.models))


def part_target(part: PartModel, name: str | None = None) -> LintTarget:
    """A base or gripper on its own, compiled and posed at ``home``."""
    gripper = isinstance(part, GripperModel)
    return _posed(name or type(part).__name__, part.compile_alone(), (part,), hangs_on_moving_body=gripper)
