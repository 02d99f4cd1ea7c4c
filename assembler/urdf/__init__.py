"""URDF robots, bases and grippers: MuJoCo's own URDF import, with its known traps disarmed.

:func:`load_urdf` turns a spec's ``urdf:`` reference into the same
:class:`~assembler.mjcf.source.MjcfSource` an MJCF file gives, so everything downstream (rules,
composition, lint, cache) works on it unchanged.
"""

from assembler.urdf.load import load_urdf, locate_urdf_file

__all__ = ["load_urdf", "locate_urdf_file"]
