"""Put a part's MJCF under a name prefix, so several parts and robots can share one model.

Prefixing goes through ``MjSpec.attach``, which renames every element and every reference to it
(actuator targets, sensor objects, tendons, assets, default classes) in one step; hand-written
renaming misses some (robosuite's list lacks ``refname`` and ``sidesite``). The assembly's
model-wide sections are the part's own, so attaching raises no option conflict.
"""

from __future__ import annotations

import mujoco

from assembler.errors import MjcfError
from assembler.mjcf.source import MjcfSource
from assembler.paths import display_path


def root_body_name(source: MjcfSource) -> str:
    """The single body directly in the file's worldbody; the part's root."""
    roots = [body.name for body in source.pristine.worldbody.bodies]
    if len(roots) != 1:
        found = ", ".join(repr(name or "(unnamed)") for name in roots) or "none"
        raise MjcfError(
            f"{display_path(source.path)}: expected exactly one body in <worldbody>, found "
            f"{len(roots)} ({found}); wrap the parts in one root body"
        )
    if not roots[0]:
        raise MjcfError(f"{display_path(source.path)}: the root body needs a name")
    return str(roots[0])


def prefixed_spec(source: MjcfSource, prefix: str) -> mujoco.MjSpec:
    """A new assembly holding a copy of ``source`` with every name prefixed by ``prefix``.

    The file's keyframes are dropped: MjSpec cannot merge keyframes of attached parts, so the
    assembler writes one ``home`` keyframe of its own (see :mod:`assembler.mjcf.keyframe`).
    """
    assembly = mujoco.MjSpec.from_string(source.globals_xml)
    part = source.new_spec()
    for key in list(part.keys):
        part.delete(key)
    assembly.attach(part, frame=assembly.worldbody.add_frame(), prefix=prefix)
    return assembly
