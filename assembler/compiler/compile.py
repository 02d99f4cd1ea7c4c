"""The one compile path: every model the assembler hands out (robots, parts alone, scenes, pictures,
cache entries, variants) is compiled here, with its ``home`` keyframe and, unless asked otherwise,
with meshes read from the mesh store. No other module names the mesh store when compiling.

:func:`compile_and_emit` compiles a spec and emits its MJCF from that same spec, with meshes read
from the mesh store for both: one assembly, one compile of ours, and MuJoCo's XML writer.

MuJoCo's XML writer (``MjSpec.to_xml``) compiles the spec again inside (MuJoCo 3.x). Emitting
after the stored meshes were taken out would make that second compile decode every OBJ and STL
file (for a Panda, 1.4 s of the 1.7 s a cold ``get_xml`` took), so the XML is written while the
meshes still read their stored ``.msh`` bytes. The only trace that leaves in the text is each
swapped mesh's ``content_type`` attribute, which is put back to the mesh's own; when that cannot
be done exactly (a mesh without a plain name, an attribute not where expected), the XML is
emitted again after the swap is undone, the slow way, so the text is always what a plain
``to_xml`` of the spec gives (tests compare them byte for byte).
"""

from __future__ import annotations

import re
from collections.abc import Callable, Mapping

import mujoco

from assembler.cache.mesh_data import MSH_CONTENT_TYPE
from assembler.cache.mesh_swap import MeshSwap, compile_from_store, use_stored_meshes
from assembler.compiler.keyframe import compile_spec, compile_with_home
from assembler.errors import MjcfError
from assembler.mjcf.emit import to_xml

_PLAIN_NAME = re.compile(r"^[A-Za-z0-9_.:\-]+$")
"""Mesh names written verbatim in the XML (no character MuJoCo's writer would escape)."""


def compile_home(
    spec: mujoco.MjSpec, home: Mapping[str, float], what: str, meshes: bool = True
) -> mujoco.MjModel:
    """Compile ``spec`` with its ``home`` keyframe (written into the spec too); meshes come from the
    mesh store unless ``meshes`` is False. ``what`` names the assembly in errors."""
    return compile_with_home(spec, home, what, compile_from_store if meshes else compile_spec)


def compile_and_emit(
    spec: mujoco.MjSpec, home: Mapping[str, float], what: str, meshes: bool = True
) -> tuple[mujoco.MjModel, str]:
    """Compile ``spec`` with its ``home`` keyframe and emit its XML (keyframe included); meshes come
    from the mesh store unless ``meshes`` is False. A compile that fails with stored meshes is run
    again from the files, whose result or error stands (as in :mod:`assembler.cache.mesh_swap`)."""
    model: mujoco.MjModel | None = None
    if meshes:
        with use_stored_meshes(spec) as swap:
            if swap.stored:
                try:
                    model = compile_with_home(spec, home, what)
                    xml = _restored(to_xml(spec), swap)
                except (MjcfError, ValueError):
                    model, xml = None, None
                if xml is not None:
                    return model, xml
    if model is None:
        model = compile_with_home(spec, home, what)
    return model, to_xml(spec)


def _restored(xml: str, swap: MeshSwap) -> str | None:
    """``xml`` with each swapped mesh's own ``content_type`` back, or None when that cannot be
    done exactly (then the caller emits again without the swap)."""
    marker = f'content_type="{MSH_CONTENT_TYPE}"'
    swapped = swap.content_types
    if any(not _PLAIN_NAME.match(name) or '"' in original or "&" in original for name, original in swapped):
        return None
    if xml.count(marker) != len(swapped):
        return None  # a mesh of the user's own that reads .msh, or one written twice: do not guess
    for name, original in swapped:
        element = re.compile(rf'(<mesh name="{re.escape(name)}"[^>]*?) {re.escape(marker)}')
        attribute = f' content_type="{original}"' if original else ""
        xml, found = element.subn(_keeping_first_group(attribute), xml)
        if found != 1:
            return None
    return xml


def _keeping_first_group(suffix: str) -> Callable[[re.Match[str]], str]:
    """A replacement that keeps a match's first group and adds ``suffix`` (literal text)."""
    return lambda match: match.group(1) + suffix
