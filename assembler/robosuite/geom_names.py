"""robosuite's names for unnamed geoms, given to our parts before they are written for robosuite.

robosuite's XML layer names every unnamed geom ``g{n}_col`` (group 0 or none) or ``g{n}_vis``
(group 1), counting per part in document order, and lists them among the part's contact or
visual geoms; the environment then looks each listed name up in the compiled model. The parts
robosuite reads and the assembly it merges must therefore name those geoms alike: both get these
names from here. Unnamed geoms of other groups (which robosuite cannot name: it raises KeyError)
are named ``g{n}_group{k}``.
"""

from __future__ import annotations

import mujoco

GROUP_SUFFIXES: dict[int, str] = {0: "col", 1: "vis"}


def name_geoms_as_robosuite(spec: mujoco.MjSpec) -> mujoco.MjSpec:
    """Give ``spec``'s unnamed geoms robosuite's names (in place); returns ``spec``."""
    counters: dict[str, int] = {}

    def visit(body: mujoco.MjsBody) -> None:
        for geom in body.geoms:
            if not geom.name:
                suffix = GROUP_SUFFIXES.get(geom.group, f"group{geom.group}")
                geom.name = f"g{counters.get(suffix, 0)}_{suffix}"
                counters[suffix] = counters.get(suffix, 0) + 1
        for child in body.bodies:
            visit(child)

    visit(spec.worldbody)
    return spec
