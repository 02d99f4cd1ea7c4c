"""Bodies whose mass depends on which geom groups count: MuJoCo infers a body's inertia from its
geoms when it has no ``<inertial>``, counting only geoms whose group is in the compiler's
``inertiagrouprange`` (MuJoCo's default: 0 to 5, every group). robosuite's world sets it to
``0 0``: there such a body weighs only its collision (group 0) geoms, not its visual ones, and the
model robosuite simulates differs from the one ``assembler build`` writes.
"""

from __future__ import annotations

import math

import mujoco


def _weighs(geom: mujoco.MjsGeom) -> bool:
    return bool(geom.mass > 0 if not math.isnan(geom.mass) else geom.density > 0)


def weighed_by_other_groups(mjspec: mujoco.MjSpec, groups: tuple[int, int]) -> list[str]:
    """The bodies of ``mjspec`` (names, in document order) without an explicit inertial that have a
    massive geom outside ``groups``: their inferred mass changes when only ``groups`` count."""
    low, high = groups
    return [
        body.name
        for body in mjspec.bodies
        if body.name != "world"
        and not body.explicitinertial
        and any(_weighs(geom) and not low <= geom.group <= high for geom in body.geoms)
    ]
