"""One body of an MJCF file and everything below it, as a part of its own (a jaw in an arm's file).

MuJoCo copies a body's subtree into another spec together with what refers only to it (actuators
and sensors of its joints, the materials and meshes it uses, its default classes). The copy is
then written out and read again, so the part is a spec of its own like any file's (its bodies'
poses taken from the file's spec, at full precision); a temporary
prefix keeps the copy's default classes apart from the new spec's own (MuJoCo 3.9 cannot write
an unprefixed copy), and is taken off every name again in the written text.
"""

from __future__ import annotations

import dataclasses

import mujoco

from assembler.errors import MjcfError
from assembler.files.paths import display_path
from assembler.mjcf import mujoco_warnings
from assembler.mjcf.emit import to_xml
from assembler.mjcf.source import MjcfSource

_PREFIX = "subtree__"
_MAIN = "subtree_main"
"""The copied file's main default class, which must not become a second class named 'main'."""


def subtree_source(source: MjcfSource, body: str) -> MjcfSource:
    """``source`` reduced to ``body`` and its descendants, the body's pose in its parent kept."""
    copy = source.new_spec()  # the attach below renames what it attaches, in place
    top = copy.body(body)
    if top is None:
        names = ", ".join(b.name for b in source.pristine.bodies[1:] if b.name)
        raise MjcfError(f"{display_path(source.path)}: no body named '{body}'; its bodies: {names}")
    part = mujoco.MjSpec()
    part.compiler.degree = source.pristine.compiler.degree
    part.worldbody.add_frame().attach_body(top, _PREFIX, "")
    with mujoco_warnings.collected():
        text = to_xml(part)  # every digit: MuJoCo's writer keeps six (ranges, masses, inertias)
    text = text.replace(f'"{_PREFIX}main"', f'"{_MAIN}"').replace(f'="{_PREFIX}', '="')
    spec = mujoco.MjSpec.from_string(text)
    for copied in spec.bodies[1:]:  # poses as given, not as written (MuJoCo writes 6 digits)
        given = copy.body(_PREFIX + copied.name)
        copied.pos, copied.quat, copied.alt = given.pos, given.quat, given.alt
    kept = {joint.name for joint in spec.joints}
    authored = tuple(
        a for j, a in zip(source.pristine.joints, source.authored, strict=True) if j.name in kept
    )
    note = f"the part is body '{body}' of the file and everything below it"
    return dataclasses.replace(source, pristine=spec, authored=authored, notes=(*source.notes, note))
