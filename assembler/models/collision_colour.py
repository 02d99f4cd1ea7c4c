"""robosuite's collision colouring, applied only where a spec asks for it (``collision_colour: robosuite``).

robosuite's own models clear the material of every collision geom (group 0) and colour it by the
part's family (green robots, blue grippers, yellow mounts). Other robots keep their file's look;
where the convention is applied, ``assembler inspect`` says so.
"""

from __future__ import annotations

from collections.abc import Sequence

import mujoco

from assembler.mjcf import COLLISION_GROUP


def colour_collision_geoms(mjspec: mujoco.MjSpec, rgba: Sequence[float]) -> None:
    """Clear every collision geom's material and give it ``rgba``, as robosuite's models do."""
    for geom in mjspec.geoms:
        if geom.group == COLLISION_GROUP:
            geom.rgba = list(rgba)
            geom.material = ""


def collision_colour_note(rgba: Sequence[float]) -> str:
    """What colouring did, for ``assembler inspect``."""
    colour = " ".join(f"{value:g}" for value in rgba)
    return (
        f"collision geoms (group 0) lose their materials and are coloured {colour} "
        "(collision_colour: robosuite)"
    )
