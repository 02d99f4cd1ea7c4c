"""Bounds on untrusted input: the most time and memory one spec or MJCF file can make us spend.

Specs and the files they name may come from strangers (a pull request checked in CI), so every
reader that a crafted file could keep busy without end stops at a limit defined here. Each limit
sits far above what a real robot needs (the largest shipped spec is about 2 KB and 60 values),
so only a crafted or broken file ever meets one. Exceeding a limit is a :class:`SpecError` or
:class:`MjcfError` naming the file, the position and the limit. SECURITY.md lists them too.
"""

from __future__ import annotations

MAX_SPEC_BYTES = 1024 * 1024
"""1 MiB per YAML file (spec, scene, experiment). Read before parsing, so a huge file costs one
bounded read; shipped specs are 1-3 KB."""

MAX_YAML_DEPTH = 64
"""Levels of nested lists and mappings. PyYAML composes nodes recursively, so a deeply nested
file (``[[[[...]]]]``) would otherwise end in a RecursionError; a spec nests four levels deep."""

MAX_YAML_VALUES = 100_000
"""Values (scalars, lists and mappings) one document may expand to. YAML aliases (``*name``)
repeat what an anchor names, so nine lines can stand for a billion values ("billion laughs");
we count while expanding and stop here. A shipped spec has under 200."""

MAX_YAML_ITEMS = 10_000
"""Items in one list or mapping. A robot with a hundred joints needs a hundred values; this
bounds per-item work in validation and in MuJoCo long before memory matters."""

MAX_MJCF_BYTES = 64 * 1024 * 1024
"""64 MiB per MJCF (XML) file, main or included. robosuite's largest is 40 KB; generated
models with inline heightfields or meshes stay well below this."""

MAX_MJCF_INCLUDE_DEPTH = 16
"""Levels of MJCF ``<include>`` files checked before MuJoCo reads them; real models use one."""

MAX_DAE_BYTES = 64 * 1024 * 1024
"""64 MiB per COLLADA (.dae) mesh converted with trimesh, read in one bounded read. The largest in
example-robot-data (go1's trunk.dae) is 29 MB; trimesh's memory grows many times the file's size."""

MAX_URDF_LINKS = 1000
"""Links in one URDF, and joints (a tree of links has one joint fewer). MuJoCo's compiler stops at a
kinematic depth of about 1,000 bodies (a chain of 1,500 links: "depth limit exceeded"), and its URDF
import crashes outright on a chain of 2,000 ("Caught an unknown exception!"); a humanoid with hands
has under 100."""

MAX_URDF_DEPTH = 64
"""Levels of nested elements in a URDF. A URDF nests about six deep (robot/link/visual/geometry/mesh);
thousands of nested ``<visual>`` would otherwise end in a RecursionError when the text is written
back for MuJoCo."""
