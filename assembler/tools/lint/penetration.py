"""RA101: parts that overlap at the home pose, e.g. a gripper mounted inside its wrist.

MuJoCo compiles such a model without complaint and then pushes the geoms apart with large contact
forces from the first step. The contacts are MuJoCo's own (``mj_forward`` at the ``home``
keyframe), so the pairs it filters (parent and child bodies, ``<exclude>``, contype/conaffinity)
are left out exactly as in simulation.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget

PENETRATION_TOLERANCE = 1e-3
"""Overlap (metres) below which contact is touching, not penetration (MuJoCo's soft contacts sink ~1 mm)."""

GEOM = mujoco.mjtObj.mjOBJ_GEOM
BODY = mujoco.mjtObj.mjOBJ_BODY


def _filtered_once_mounted(model: mujoco.MjModel, first: int, second: int) -> bool:
    """MuJoCo's parent-child filter as it will act when the world-welded root hangs off a moving hand.

    MuJoCo never filters pairs whose parent is welded to the world; a gripper linted alone is, but in
    use its root is welded to the arm's hand, where the filter does apply.
    """
    welds = [int(model.body_weldid[model.geom_bodyid[g]]) for g in (first, second)]
    parents = [int(model.body_weldid[model.body_parentid[w]]) for w in welds]
    return welds[0] == parents[1] or welds[1] == parents[0]


def self_penetration(target: LintTarget) -> Iterator[Finding]:
    """RA101 (error): geoms of different bodies overlap by more than 1 mm at the home pose."""
    model, data = target.model, target.data
    deepest: dict[tuple[int, int], float] = {}
    for contact in data.contact[: data.ncon]:
        pair = (int(min(contact.geom1, contact.geom2)), int(max(contact.geom1, contact.geom2)))
        deepest[pair] = max(deepest.get(pair, 0.0), -float(contact.dist))
    for (first, second), depth in sorted(deepest.items()):
        if depth <= PENETRATION_TOLERANCE:
            continue
        if target.hangs_on_moving_body and _filtered_once_mounted(model, first, second):
            continue
        bodies = [target.element_name(BODY, int(model.geom_bodyid[g])) for g in (first, second)]
        names = [  # an unnamed geom is told by its body, which also tells whose it is
            target.element_name(GEOM, g) if mujoco.mj_id2name(model, GEOM, g) else f"geom #{g} ({body})"
            for g, body in zip((first, second), bodies, strict=True)
        ]
        # The later geom usually belongs to the part attached last (a gripper), the one to move.
        named = names[1] if mujoco.mj_id2name(model, GEOM, second) else bodies[1]
        location = target.element_location(("geom",) if named == names[1] else ("body",), named)
        yield Finding(
            code="RA101",
            severity="error",
            subject=f"{names[0]} / {names[1]}",
            why=(
                f"geoms of bodies {bodies[0]} and {bodies[1]} overlap by {depth * 1000:.1f} mm at the "
                "home pose; MuJoCo pushes them apart with large contact forces from the first step"
            ),
            fix=(
                "move the part (gripper_mount, the body's pos) or change init_qpos so they clear; if they "
                "really touch by design, exclude the pair with <contact><exclude> in the MJCF"
            ),
            location=location,
        )
