"""RA504: a part with no visual geoms, invisible to robosuite's cameras and viewer.

robosuite hides geom group 0 (collision) in its renderers and draws group 1 (visual), so a part
whose geoms are all collision geoms, common in hand-written and URDF-derived MJCF, is missing
from every camera observation, while it still collides. ``assembler render`` draws such a part's
collision geoms instead (and says so); this check says it where a reviewer looks.
"""

from __future__ import annotations

from collections.abc import Iterator

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.mjcf import COLLISION_GROUP, VISUAL_GROUPS
from assembler.models.geom_groups import geoms_by_part
from assembler.spec.fieldpath import FieldPath


def invisible_parts(target: LintTarget) -> Iterator[Finding]:
    """RA504 (warning): a part has geoms, none of them in a visual group (1 or 2)."""
    for part in geoms_by_part(target.model, target.parts):
        if not part.collision_only:
            continue
        groups = ", ".join(str(group) for group in part.groups)
        yield Finding(
            code="RA504",
            severity="warning",
            subject=part.part.root_body,
            why=(
                f"{part.name} has {len(part.geoms)} geom(s), all in group(s) {groups} and none in the "
                f"visual groups {', '.join(str(g) for g in VISUAL_GROUPS)}: robosuite's cameras and viewer "
                f"hide group {COLLISION_GROUP}, so it is invisible there (assembler render draws its "
                "collision geoms instead)"
            ),
            fix=(
                'add visual geoms in group 1 with contype="0" conaffinity="0" (copies of the collision '
                'geoms will do), or put geoms meant to be seen in group="1"'
            ),
            location=target.spec_location(part.part, FieldPath(("mjcf",))),
        )
