"""Which geoms of an assembly are seen: each part's visual geoms, or its collision geoms if it has none.

robosuite's convention puts collision geoms in group 0 and visual geoms in group 1 (group 2 is
drawn too), and its cameras and viewer hide group 0. Hand-written and URDF-derived MJCF often
has collision geoms only; such a part is invisible there. A picture (``assembler render``) shows
each part what it has: its visual groups, else its collision group; ``assembler lint`` reports
the part (RA504). Geoms are assigned to parts by the prefix their name carries (or, for an
unnamed geom, the nearest named body above it), as lint traces every element.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco

from assembler.mjcf import COLLISION_GROUP, VISUAL_GROUPS
from assembler.models.part import PartModel


@dataclass(frozen=True)
class PartGeoms:
    """One part's geoms in a compiled assembly, and the groups they are in."""

    part: PartModel
    geoms: tuple[int, ...]
    groups: tuple[int, ...]
    """The distinct groups of its geoms, in order."""

    @property
    def name(self) -> str:
        """The part as users name it: its class (the spec's name)."""
        return type(self.part).__name__

    @property
    def collision_only(self) -> bool:
        """It has geoms, and none of them is in a visual group."""
        return bool(self.geoms) and not set(self.groups) & set(VISUAL_GROUPS)

    def seen(self) -> tuple[int, ...]:
        """The groups a picture shows of it by default: visual ones, or collision if it has none."""
        return (COLLISION_GROUP,) if self.collision_only else VISUAL_GROUPS


def _owner_name(model: mujoco.MjModel, geom: int) -> str:
    """The geom's name, else the name of the nearest named body that holds it."""
    name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_GEOM, geom)
    body = int(model.geom_bodyid[geom])
    while not name and body > 0:
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_BODY, body)
        body = int(model.body_parentid[body])
    return name or ""


def geoms_by_part(model: mujoco.MjModel, parts: Sequence[PartModel]) -> list[PartGeoms]:
    """Each part's geoms (by the longest name prefix that matches); geoms of no part are left out."""
    owned: dict[int, list[int]] = {index: [] for index in range(len(parts))}
    for geom in range(model.ngeom):
        name = _owner_name(model, geom)
        owners = [index for index, part in enumerate(parts) if name.startswith(part.naming_prefix)]
        if owners:
            owned[max(owners, key=lambda index: len(parts[index].naming_prefix))].append(geom)
    return [
        PartGeoms(
            part=parts[index],
            geoms=tuple(geoms),
            groups=tuple(sorted({int(model.geom_group[geom]) for geom in geoms})),
        )
        for index, geoms in owned.items()
    ]


def _listed(groups: Sequence[int]) -> str:
    return f"geom group{'s' if len(groups) != 1 else ''} {', '.join(str(g) for g in groups)}"


def describe(parts: Sequence[PartGeoms], chosen: Sequence[int] | None) -> str:
    """Which groups a picture drew, e.g. ``geom groups 1, 2; group 0 for Blocky: it has no visual geoms``."""
    if chosen is not None:
        return _listed(chosen)
    bare = [part.name for part in parts if part.collision_only]
    if not bare:
        return _listed(VISUAL_GROUPS)
    they = "it has" if len(bare) == 1 else "they have"
    reason = f"{', '.join(bare)}: {they} no visual geoms"
    if len(bare) == len([part for part in parts if part.geoms]):
        return f"{_listed([COLLISION_GROUP])} (collision) for {reason}"
    return f"{_listed(VISUAL_GROUPS)}; group {COLLISION_GROUP} (collision) for {reason}"
