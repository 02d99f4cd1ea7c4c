"""The one layer that touches MuJoCo's model editing (MjSpec): load, prefix, attach, compile, emit.

It also defines, once and below every layer that sorts geoms (the URDF importer, parts, pictures,
lint), the geom groups our parts use, as robosuite does: collision geoms in group 0, visual geoms in 1.
They are plain numbers here so that reading them (``assembler --help`` does) imports neither MuJoCo
nor numpy.
"""

COLLISION_GROUP = 0
"""robosuite's group for collision geoms."""

VISUAL_GROUP = 1
"""robosuite's group for visual geoms (group 2 is visual too in some of its models)."""

VISUAL_GROUPS: tuple[int, ...] = (1, 2)
"""Groups whose geoms are drawn and do not collide, by robosuite's convention."""

GROUP_COUNT = 6
"""MuJoCo's geom groups are 0 to 5 (``mjNGROUP``); a picture draws 0-2 unless told otherwise."""
