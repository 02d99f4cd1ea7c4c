"""Loading an MJCF file once: a pristine MjSpec with absolute asset paths, plus what we learn from
it; and the part a file gives: its single, named root body, or one body and everything below it.

Each robot instance gets a cheap copy of the pristine spec. Asset paths are made absolute (and
``meshdir``/``texturedir`` cleared) before anything is attached, because ``MjSpec.to_xml`` keeps only
the outermost model's directories: without this the emitted XML would not load from another
working directory. Every asset path must stay in the allowed folders (:func:`assembler.files.paths.confine`),
and the file passes :mod:`assembler.mjcf.xml_guard` before any parser reads it. Once read, the file
is compiled on its own as MuJoCo would (:func:`assembler.mjcf.xml_guard.check_as_mujoco`): what
MuJoCo refuses is refused here, with the file's line, rather than dropped by ``MjSpec.attach`` later.

One body of an MJCF file and everything below it can be a part of its own (a jaw in an arm's file:
:func:`subtree_source`). MuJoCo copies a body's subtree into another spec together with what refers
only to it (actuators and sensors of its joints, the materials and meshes it uses, its default
classes). The copy is then written out and read again, so the part is a spec of its own like any
file's (its bodies' poses taken from the file's spec, at full precision); a temporary prefix keeps
the copy's default classes apart from the new spec's own (MuJoCo 3.9 cannot write an unprefixed
copy), and is taken off every name again in the written text.
"""

from __future__ import annotations

import dataclasses
import functools
import os
import warnings
import xml.etree.ElementTree as ET
from collections.abc import Collection, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path

import mujoco
from pydantic import TypeAdapter

from assembler.errors import AssemblerWarning, MjcfError, Problem
from assembler.files.inputs import note_inputs
from assembler.files.paths import allowed_folders, confine, display_path, homes_of, locate_model_file
from assembler.files.regular import not_regular
from assembler.mjcf import installed_mujoco
from assembler.mjcf.actuator_defaults import normalize_actuator_defaults
from assembler.mjcf.compose import refuse_unattachable, settle_default_site_materials
from assembler.mjcf.emit import to_xml
from assembler.mjcf.fixes import apply_fixes
from assembler.mjcf.joints import Authored, authored_attributes, named_joints
from assembler.mjcf.xml_guard import (
    LineMap,
    check_as_mujoco,
    check_mjcf,
    name_assets_after_files,
    non_finite_values,
    original_lines,
    refusal_line,
    repaired_lines,
    same_lines,
)
from assembler.spec.schema.fixes import MjcfFix

GLOBAL_SECTIONS: tuple[str, ...] = ("compiler", "option", "size", "visual", "statistic")
"""Model-wide sections a standalone robot keeps from its own file (e.g. its integrator)."""

DIRECTORY_ATTRIBUTES: tuple[str, ...] = ("meshdir", "texturedir", "assetdir")

_FIXES = TypeAdapter(list[MjcfFix])

_SUBTREE_PREFIX = "subtree__"
_SUBTREE_MAIN = "subtree_main"
"""A subtree part's main default class, which must not become a second class named 'main'."""


@dataclass(frozen=True)
class MjcfSource:
    """One parsed MJCF file: pristine spec, its global sections, and the joints' authored attributes."""

    path: Path
    pristine: mujoco.MjSpec
    globals_xml: str
    authored: tuple[Authored, ...]
    files: tuple[tuple[str, int, int], ...] = ()
    """The file and every file it includes, as (path, size, mtime_ns) when they were read."""
    velocity_limits: Mapping[str, float] = field(default_factory=dict)
    """Joint velocity limits the file gives (a URDF's ``<limit velocity>``; MJCF has none)."""
    notes: tuple[str, ...] = ()
    """What loading changed in the file as written, for ``assembler inspect``."""

    def is_current(self) -> bool:
        """True while none of the files read to make this source has changed on disk."""
        return all(_stat(path) == (size, mtime_ns) for path, size, mtime_ns in self.files)

    def new_spec(self) -> mujoco.MjSpec:
        """A fresh, independent copy of the file's spec to attach or edit."""
        return self.pristine.copy()

    @property
    def joint_names(self) -> list[str]:
        """Names of the file's joints in MuJoCo's order, free joints excluded."""
        return named_joints(self.pristine)


def _asset_file(directory: str, mjcf: Path, file: str, homes: Collection[Path]) -> str:
    """The absolute path of an asset of the file ``mjcf``; it must stay in the allowed folders (MuJoCo
    reads it at compile; a refusal names the file), and it is noted as an input no output may replace."""
    if not file:
        return file
    path = Path(file) if os.path.isabs(file) else mjcf.parent / directory / file
    confined = str(confine(path, homes, f"{display_path(mjcf)}: asset file ", MjcfError))
    note_inputs([confined])
    return confined


MESH_CONTENT_TYPES: dict[str, str] = {
    ".stl": "model/stl",
    ".obj": "model/obj",
    ".msh": "model/vnd.mujoco.msh",
}
"""A mesh file's content type by its suffix, as MuJoCo 4's XML writer names it. Written into every
mesh that does not say, so the emitted XML is the same whether or not MuJoCo decoded the file in
this process (MuJoCo 3.9 writes the type only for meshes it has just decoded)."""


def name_mesh_content_types(spec: mujoco.MjSpec) -> None:
    """Write :data:`MESH_CONTENT_TYPES` into every mesh of ``spec`` that does not say its type (an
    MJCF's or a URDF's), so its XML does not depend on what MuJoCo decoded in this process."""
    for mesh in spec.meshes:
        if mesh.file and not mesh.content_type:
            mesh.content_type = MESH_CONTENT_TYPES.get(Path(mesh.file).suffix.lower(), "")


def _absolutize_assets(spec: mujoco.MjSpec, mjcf: Path, homes: Collection[Path]) -> list[str]:
    """Rewrite every asset file path to an absolute one; return those that do not exist."""
    missing = []
    mesh_dir, texture_dir = spec.meshdir or "", spec.texturedir or ""
    groups = [(spec.meshes, mesh_dir), (spec.hfields, mesh_dir), (spec.skins, mesh_dir)]
    for elements, directory in groups:
        for element in elements:
            element.file = _asset_file(directory, mjcf, element.file, homes)
            if element.file and not os.path.isfile(element.file):
                missing.append(element.file)
    name_mesh_content_types(spec)
    for texture in spec.textures:
        texture.file = _asset_file(texture_dir, mjcf, texture.file, homes)
        texture.cubefiles = [_asset_file(texture_dir, mjcf, f, homes) for f in texture.cubefiles]
        for file in [texture.file, *texture.cubefiles]:
            if file and not os.path.isfile(file):
                missing.append(file)
    spec.meshdir = ""
    spec.texturedir = ""
    return missing


def _globals_xml(root: ET.Element) -> str:
    skeleton = ET.Element("mujoco", {"model": root.get("model", "robot")})
    for tag in GLOBAL_SECTIONS:
        element = root.find(tag)
        if element is None:
            continue
        element = ET.fromstring(ET.tostring(element))
        for attribute in DIRECTORY_ATTRIBUTES:
            element.attrib.pop(attribute, None)
        skeleton.append(element)
    return ET.tostring(skeleton, encoding="unicode")


def _unnamed_joints(spec: mujoco.MjSpec) -> list[str]:
    return [
        f"in body '{j.parent.name or '(unnamed)'}'"
        for j in spec.joints
        if not j.name and j.type != mujoco.mjtJoint.mjJNT_FREE
    ]


def _parse(
    path: Path, fixes: Sequence[MjcfFix], included: Mapping[str, bytes]
) -> tuple[ET.Element, mujoco.MjSpec, LineMap, dict[str, bytes]]:
    """The file's XML tree and MjSpec, after its declared repairs, the map from the lines MuJoCo
    reports to the file's own, and the included files' texts as MuJoCo read them (``included``:
    each ``<include file>`` value -> the file's bytes on disk; repairs apply to them too)."""
    shown = display_path(path)
    lines: LineMap = same_lines
    try:
        root = ET.parse(path).getroot()
        if not fixes:
            with installed_mujoco.warned(shown):
                return root, mujoco.MjSpec.from_file(str(path)), lines, dict(included)
        original = original_lines(root, path.read_bytes())
        others = {name: ET.fromstring(text) for name, text in included.items()}
        stale = apply_fixes([root, *others.values()], fixes)
        if stale:
            raise MjcfError([Problem(f"{shown}: {line}") for line in stale])
        emptied = {name for name, other in others.items() if len(other) == 0 and len(included[name].strip())}
        for tree in [root, *others.values()]:  # MuJoCo refuses an empty include file: the repairs emptied
            for parent in list(tree.iter()):  # it (a scene's other arm), so its <include> goes with it
                for child in [c for c in parent if c.tag == "include" and c.get("file") in emptied]:
                    parent.remove(child)
        repaired = {
            name: ET.tostring(other, encoding="utf-8")
            for name, other in others.items()
            if name not in emptied
        }
        # Parsed from text: asset paths stay relative and are resolved against the file's folder below;
        # the included files are handed over repaired, by the names the <include>s give.
        text = ET.tostring(root, encoding="unicode")
        lines = repaired_lines(root, text, original)
        with installed_mujoco.warned(shown):
            spec = mujoco.MjSpec.from_string(text, include=repaired)
        _unprefix_included_assets(spec, {name: others[name] for name in repaired})
        return root, spec, lines, repaired
    except ET.ParseError as error:
        raise MjcfError(f"{shown}: not well-formed XML: {error}") from None
    except ValueError as error:
        raise MjcfError(refusal_line(str(error), shown, lines, "MuJoCo cannot read it")) from None


ASSET_TAGS = ("mesh", "texture", "hfield", "skin")


def _unprefix_included_assets(spec: mujoco.MjSpec, included: Mapping[str, ET.Element]) -> None:
    """Asset paths of included files as MuJoCo reads the file itself: relative to the main file's folder.

    Handed an included file through ``from_string(include=...)``, MuJoCo prefixes the include's own
    folder to the paths of the assets it declares (unless that name happens to exist from the working
    folder), where ``from_file`` does not: metaworld's ``../objects/assets/block_dependencies.xml``
    names ``../objects/meshes/block/block.stl``, which would become ``../objects/objects/meshes/...``."""
    original: dict[str, str] = {}
    for name, tree in included.items():
        folder = os.path.dirname(name)
        if not folder:
            continue
        for element in tree.iter():
            if element.tag in ASSET_TAGS and element.get("file"):
                written = element.get("file", "")
                original[os.path.normpath(os.path.join(folder, written))] = written
    if not original:
        return
    for elements in (spec.meshes, spec.hfields, spec.skins, spec.textures):
        for element in elements:
            if element.file in original:
                element.file = original[element.file]


def _stat(path: str) -> tuple[int, int] | None:
    try:
        stat = os.stat(path)
    except OSError:
        return None
    return stat.st_size, stat.st_mtime_ns


def _included_texts(path: Path, read: Sequence[Path]) -> dict[str, bytes]:
    """Each ``<include file>`` value of the file and its includes, mapped to the included bytes
    (``read``: the files :func:`check_mjcf` found and confined; MuJoCo resolves includes against
    the main file's folder)."""
    confined = {str(file) for file in read}
    texts: dict[str, bytes] = {}
    for file in read:
        if file.suffix.lower() != ".xml":
            continue
        for element in ET.parse(file).getroot().iter("include"):
            name = element.get("file") or ""
            target = str((path.parent / name).resolve())
            if name and target in confined:
                texts[name] = Path(target).read_bytes()
    return texts


@functools.lru_cache(maxsize=64)
def _load(path: Path, mtime_ns: int, size: int, fixes_json: str, homes: frozenset[Path]) -> MjcfSource:
    shown = display_path(path)
    read = check_mjcf(path, homes)  # size, no DTD, includes confined: before any parser expands anything
    # Stat before parsing: a file edited while we read it then shows a newer stat than recorded.
    files = tuple((str(file), *stat) for file in read if (stat := _stat(str(file))) is not None)
    fixes = _FIXES.validate_json(fixes_json)
    on_disk = _included_texts(path, read)
    root, spec, lines, included = _parse(path, fixes, on_disk)
    normalize_actuator_defaults(root, spec, included)  # MuJoCo < 3.16 leaks other shortcuts' gains
    unnamed = _unnamed_joints(spec)
    if unnamed:
        raise MjcfError(f"{shown}: every joint needs a name; unnamed joint {unnamed[0]}")
    name_assets_after_files(spec)  # before attaching prefixes the names: MuJoCo derives them at compile
    missing = _absolutize_assets(spec, path, homes)
    if missing:
        kind = not_regular(missing[0])  # a FIFO, a device or a folder is there: say what it is
        if kind is not None:
            raise MjcfError(f"{shown}: asset file {display_path(missing[0])}: {kind}")
        raise MjcfError(f"{shown}: asset file not found: {display_path(missing[0])}")
    spec = settle_default_site_materials(spec)
    not_finite = [
        line
        for file in read
        if file.suffix.lower() == ".xml"
        for line in non_finite_values(file.read_bytes(), display_path(file), "the file")
    ]
    for line in not_finite:  # said once per version of the file, as MuJoCo's own warnings are, and
        warnings.warn(line, AssemblerWarning, stacklevel=2)  # before MuJoCo 3.9 refuses a NaN itself
    # A second parse for the check: MjSpec.copy() itself drops what it cannot resolve, in silence.
    check_as_mujoco(_parse(path, fixes, on_disk)[1], spec, shown, lines)
    refuse_unattachable(spec, shown)
    return MjcfSource(
        path=path,
        pristine=spec,
        globals_xml=_globals_xml(root),
        authored=tuple(authored_attributes(root, spec, included)),
        files=files,
        notes=tuple(not_finite),
    )


def load_mjcf(reference: str, fixes: Sequence[MjcfFix] = ()) -> MjcfSource:
    """The parsed MJCF behind a spec's ``mjcf`` reference, repaired as the spec declares; re-read
    only when the file or the repairs change."""
    path = locate_model_file(reference).resolve()
    stat = path.stat()
    # Its assets may lie below the folders that admitted it (a spec's folder, a package) or its own.
    homes = frozenset({path.parent, *homes_of(path), *allowed_folders()})
    arguments = (path, stat.st_mtime_ns, stat.st_size, _FIXES.dump_json(list(fixes)).decode(), homes)
    source = _load(*arguments)
    if not source.is_current():  # an included file changed: the remembered parse is stale
        _load.cache_clear()
        source = _load(*arguments)
    return source


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


def subtree_source(source: MjcfSource, body: str) -> MjcfSource:
    """``source`` reduced to ``body`` and its descendants, the body's pose in its parent kept."""
    copy = source.new_spec()  # the attach below renames what it attaches, in place
    top = copy.body(body)
    if top is None:
        names = ", ".join(b.name for b in source.pristine.bodies[1:] if b.name)
        raise MjcfError(f"{display_path(source.path)}: no body named '{body}'; its bodies: {names}")
    part = mujoco.MjSpec()
    part.compiler.degree = source.pristine.compiler.degree
    part.option, part.visual = copy.option, copy.visual  # the file's: no conflict for attach to warn of
    part.worldbody.add_frame().attach_body(top, _SUBTREE_PREFIX, "")
    with installed_mujoco.collected():
        text = to_xml(part)  # every digit: MuJoCo's writer keeps six (ranges, masses, inertias)
    text = text.replace(f'"{_SUBTREE_PREFIX}main"', f'"{_SUBTREE_MAIN}"').replace(
        f'="{_SUBTREE_PREFIX}', '="'
    )
    spec = mujoco.MjSpec.from_string(text)
    for copied in spec.bodies[1:]:  # poses as given, not as written (MuJoCo writes 6 digits)
        given = copy.body(_SUBTREE_PREFIX + copied.name)
        copied.pos, copied.quat, copied.alt = given.pos, given.quat, given.alt
    kept = {joint.name for joint in spec.joints}
    authored = tuple(
        a for j, a in zip(source.pristine.joints, source.authored, strict=True) if j.name in kept
    )
    note = f"the part is body '{body}' of the file and everything below it"
    return dataclasses.replace(source, pristine=spec, authored=authored, notes=(*source.notes, note))
