"""A legged base (robosuite's LegBaseModel), prefix ``leg{idn}_``: like a mobile base, and its free
joint (if any) moves to the robot's root, which also keeps the robot root's inertia."""

from __future__ import annotations

from assembler.models.bases.mobile import MobileBaseModel


class LegBaseModel(MobileBaseModel):
    """Legs carrying the robot; its joints belong to the legs unless the spec says otherwise."""

    in_registry = False
    prefix_stem = "leg"
    default_group = "legs"
    legged = True
