"""A vendor's MJCF file, checked before ElementTree or MuJoCo parses it, then as MuJoCo checks it,
and what MuJoCo refuses said as one located line.

**Before parsing.** A spec's MJCF may come from a pull request, so before any full parser sees it
we check, with a streaming pass of expat that builds nothing:

- its size (:data:`assembler.files.limits.MAX_MJCF_BYTES`);
- that it has no document type declaration: a DTD is where XML entities are declared, and both
  entity expansion ("billion laughs") and external entities (which read other local files) start
  there. MJCF never needs one;
- that every file it pulls in while parsing (``<include file>``, ``<model file>``) stays in the
  allowed folders and passes the same checks, to :data:`assembler.files.limits.MAX_MJCF_INCLUDE_DEPTH`.

Meshes and textures are read later, at compile time; :mod:`assembler.mjcf.source` confines them.

**As MuJoCo checks it**, before anything of it is attached. ``MjSpec.attach`` silently drops what
it cannot resolve: an actuator on a joint that does not exist, a sensor of a missing site, a tendon
through a missing joint, an equality, contact pair or exclude naming a missing body or geom, a skin
bone... MuJoCo compiling the file itself refuses every one of them (and so does ``MjSpec.copy()``:
the check compiles a spec freshly parsed, never a copy). So each file is compiled once on its own,
as MuJoCo would (after its declared ``mjcf_fixes``, asset paths absolute), and a refusal becomes
one located problem (below). The check runs once per file version:
:func:`assembler.mjcf.source.load_mjcf` caches its result.

Two departures from compiling the file as it is, each chosen on purpose:

- **Cost.** Decoding meshes and textures is most of a compile: the first compile of robosuite's
  Panda or GR1 takes about a second, which a robot read from the compiled-model cache would
  otherwise pay on every load. The probe replaces each file-backed mesh by a tetrahedron, each
  file-backed texture by a 2x2 flat one and each file-backed height field by a 2x2 flat one,
  keeping names, kinds and everything that refers to them: every reference MuJoCo checks is still
  checked, for a few milliseconds (measured: ~3 ms to compile the probe of Panda or GR1, plus a
  second parse of the file). Skin files are read, since they name bodies. What the probe no longer
  sees is the contents of the other files (a mesh of zero volume, say); the assembly's own compile
  reads them and refuses such a file, so nothing is dropped in silence.
- **Mass.** A part may be valid only with what the assembly puts on it: robosuite's NullMobileBase
  has a massless moving support that the robot standing on it weighs down (MuJoCo alone says "mass
  and inertia of moving bodies must be larger than mjMINVAL"). The probe raises the compiler's
  ``boundmass``/``boundinertia`` to a tiny floor, so a massless body passes here and is judged by
  the assembly's compile, where it still fails loudly if nothing gives it mass.

**Unnamed assets.** MuJoCo names an unnamed ``<mesh file="base_so101_v2.stl"/>`` after its file
(``base_so101_v2``) when it compiles it, and geoms refer to it by that name; so are unnamed textures
and height fields. The name exists only at compile time, so whatever changes or blanks the file
before then (the check's stand-ins) or attaches the asset under a prefix (an assembly) would lose
it: the rule is applied once, on the parsed spec, and the asset keeps the name MuJoCo would have
given it (:func:`name_assets_after_files`).

**A refusal, located.** MuJoCo ends its error text with where the element sits: ``Element name
'a1', id 0, line 33`` when compiling, ``Element 'geom', line 24`` when parsing. Line 0 means an
element read from an ``<include>``d file, whose line MuJoCo does not keep; then the element's name
stands in for the line. A file repaired by its spec's ``mjcf_fixes`` is parsed from the repaired
text, not from disk, so MuJoCo's line numbers count lines of that text. :func:`repaired_lines` maps
them back to the file the user can open: ElementTree drops comments and the XML declaration and
folds attribute values that span lines, so the two texts' lines differ. Both texts are read by
expat, whose start tags come in the same order as ``Element.iter()``, which pairs each element with
its two lines.
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET
import xml.parsers.expat
from collections.abc import Callable, Collection
from pathlib import Path, PurePath

import mujoco

from assembler.errors import MjcfError
from assembler.files.inputs import note_inputs
from assembler.files.limits import MAX_MJCF_BYTES, MAX_MJCF_INCLUDE_DEPTH
from assembler.files.paths import confine, display_path
from assembler.files.regular import FileTooLarge, not_regular, read_bounded
from assembler.mjcf import installed_mujoco

FILE_ELEMENTS: tuple[str, ...] = ("include", "model", "flexcomp")
"""Elements whose ``file`` MuJoCo reads while parsing the XML (meshes and textures are read at
compile time and checked after parsing)."""

DIRECTORY_ATTRIBUTES: tuple[str, ...] = ("meshdir", "assetdir")
"""``<compiler>`` folders a parse-time file (a flexcomp's mesh) may be taken relative to."""

LineMap = Callable[[int], "int | None"]
"""MuJoCo's line number -> the line in the file on disk (None: not in that file)."""


NOT_FINITE = "not a finite number"
"""The words of every line saying that a model file's number is NaN or infinite."""

NON_FINITE_VALUE = re.compile(r"(?<![A-Za-z_])[-+]?(nan|inf|infinity)(?![A-Za-z_])", re.IGNORECASE)

TEXT_ATTRIBUTES = frozenset(
    {
        "name", "class", "childclass", "file", "filename", "content_type", "type", "link", "joint",
        "joint1", "joint2", "body", "body1", "body2", "geom", "geom1", "geom2", "site", "site1", "site2",
        "tendon", "actuator", "mesh", "material", "texture", "hfield", "skin", "target", "objtype",
        "objname", "reftype", "refname", "prefix", "key", "plugin", "instance", "model", "mode",
    }
)  # fmt: skip
"""Attributes of MJCF and URDF that hold names or words, never numbers (a body may be named ``inf``)."""


def non_finite_values(data: bytes, shown: str, file: str) -> list[str]:
    """A line per attribute of the model file (its bytes ``data``, shown as ``shown``; ``file``: what to
    correct, e.g. "the URDF") whose value holds ``nan`` or ``inf``: MuJoCo keeps them (a NaN position
    makes every step NaN, an infinite size a geom without bounds) and warns only that the file holds a
    NaN somewhere, or nothing for an infinity."""
    kept = (
        "MuJoCo keeps it as written (a NaN position makes every step NaN, an infinite size a geom "
        f"without bounds); correct {file}"
    )
    found = []
    text = data.decode("utf-8", errors="replace")
    for number, line in enumerate(text.splitlines(), start=1):
        for tag, body in re.findall(r"<(\w+)([^<>]*)>", line):
            for attribute, value in re.findall(r"([\w:]+)\s*=\s*[\"']([^\"']*)[\"']", body):
                if attribute not in TEXT_ATTRIBUTES and NON_FINITE_VALUE.search(value):
                    written = f'<{tag} {attribute}="{value}">'
                    found.append(f"{shown}:{number}: {written} holds a value that is {NOT_FINITE}: {kept}")
    return found


class _Refused(Exception):
    """Raised inside an expat handler to stop the parse at once."""


def _read(path: Path) -> bytes:
    shown = display_path(path)
    try:
        data = read_bounded(path, MAX_MJCF_BYTES)
    except FileTooLarge as error:
        raise MjcfError(f"{shown}: {error.strerror} for MJCF") from None
    except OSError as error:
        raise MjcfError(f"{shown}: cannot read the file: {error.strerror}") from None
    note_inputs([path])  # an MJCF, an included file or a URDF: no output may replace it
    return data


def _files_named(data: bytes, shown: str) -> tuple[list[tuple[str, str]], list[str]]:
    """(element, file) of every file read while parsing, and the compiler's folders; refuses a
    DTD before anything is expanded."""
    parser = xml.parsers.expat.ParserCreate()
    named: list[tuple[str, str]] = []
    folders: list[str] = []

    def doctype(*_: object) -> None:
        raise _Refused(
            f"{shown}: a document type declaration (<!DOCTYPE ...>) is not allowed in MJCF: "
            "XML entities are declared there and their expansion is unbounded; remove it"
        )

    def start(name: str, attributes: dict[str, str]) -> None:
        if name in FILE_ELEMENTS and attributes.get("file"):
            named.append((name, attributes["file"]))
        if name == "compiler":
            folders.extend(attributes[key] for key in DIRECTORY_ATTRIBUTES if attributes.get(key))

    parser.StartDoctypeDeclHandler = doctype
    parser.StartElementHandler = start
    try:
        parser.Parse(data, True)
    except _Refused as refused:
        raise MjcfError(str(refused)) from None
    except (xml.parsers.expat.ExpatError, LookupError) as error:  # LookupError: <?xml encoding="x"?>
        raise MjcfError(f"{shown}: not well-formed XML: {error}") from None
    return named, folders


def check_mjcf(path: Path, homes: Collection[Path]) -> list[Path]:
    """Refuse ``path`` (an MJCF file) if it or a file it includes is too large, declares a DTD, or
    includes a file outside ``homes`` and the trusted folders. Return every existing file it names
    through ``<include>``, ``<model>`` or ``<flexcomp>`` (resolved), after ``path`` itself."""
    main_folder = path.parent
    named: list[Path] = [path]
    pending: list[tuple[Path, int]] = [(path, 0)]
    seen: set[Path] = set()
    while pending:
        current, depth = pending.pop()
        if current in seen:
            continue
        seen.add(current)
        shown = display_path(current)
        files, folders = _files_named(_read(current), shown)
        for element, file in files:
            if depth + 1 > MAX_MJCF_INCLUDE_DEPTH:
                raise MjcfError(
                    f"{shown}: included files nest deeper than the limit of {MAX_MJCF_INCLUDE_DEPTH} levels"
                )
            # MuJoCo takes include paths relative to the main file (a flexcomp's mesh relative to
            # meshdir); check every folder it could mean, so no reading leaves the allowed ones.
            bases = (main_folder, current.parent, *(main_folder / folder for folder in folders))
            for folder in dict.fromkeys(bases):
                included = confine(folder / file, homes, f"{shown}: <{element}> file ", MjcfError)
                kind = not_regular(included)
                if kind is not None:  # MuJoCo would open it itself: a FIFO would hang the process
                    raise MjcfError(f"{shown}: <{element}> file {display_path(included)}: {kind}")
                if included.is_file() and included not in named:
                    named.append(included)
                    note_inputs([included])  # a flexcomp's mesh too, which is not read here
                if element != "flexcomp" and included.is_file():  # XML: check what it includes
                    pending.append((included, depth + 1))
    return named


def file_stem(file: str) -> str:
    """The name MuJoCo gives an unnamed asset: its file name without folder and extension."""
    return PurePath(file.replace("\\", "/")).stem


def name_assets_after_files(spec: mujoco.MjSpec) -> None:
    """Give every unnamed mesh, texture and height field with a file the name MuJoCo would derive."""
    for asset in [*spec.meshes, *spec.textures, *spec.hfields]:
        if not asset.name and asset.file:
            asset.name = file_stem(asset.file)


TETRAHEDRON: tuple[float, ...] = (0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1)
"""Vertices of the stand-in mesh: positive volume at any scale a mesh is given (1e-3 -> 1.7e-10 m^3)."""

MASS_FLOOR = 1e-6
"""kg, and kg m^2 for inertia: well above MuJoCo's mjMINVAL (1e-15), negligible next to any real part."""


def _stand_in_assets(spec: mujoco.MjSpec, resolved: mujoco.MjSpec) -> None:
    """Replace the contents of file-backed meshes, textures and height fields (names stay); skins
    keep their files, which name bones, read from the paths already resolved in ``resolved``. An
    unnamed asset first takes its file's name, as MuJoCo would have given it from the file."""
    name_assets_after_files(spec)
    spec.meshdir = spec.texturedir = ""
    for skin, same in zip(spec.skins, resolved.skins, strict=True):
        skin.file = same.file
    for mesh in spec.meshes:
        if mesh.file:
            mesh.file = ""
            mesh.content_type = ""
            mesh.uservert = list(TETRAHEDRON)
    for texture in spec.textures:
        if texture.file or any(texture.cubefiles):
            texture.file = ""
            texture.content_type = ""
            texture.cubefiles = [""] * 6
            texture.builtin = mujoco.mjtBuiltin.mjBUILTIN_FLAT
            texture.width = texture.height = 2
    for hfield in spec.hfields:
        if hfield.file:
            hfield.file = ""
            hfield.content_type = ""
            hfield.nrow = hfield.ncol = 2
            hfield.userdata = [0.0] * 4


def check_as_mujoco(probe: mujoco.MjSpec, resolved: mujoco.MjSpec, shown: str, lines: LineMap) -> None:
    """Refuse the file (displayed as ``shown``) if MuJoCo refuses to compile it; ``lines`` maps
    MuJoCo's line numbers to the file's.

    ``probe`` must come straight from parsing the file and is used up: its assets are replaced.
    Not a copy of a spec: ``MjSpec.copy()`` drops what it cannot resolve, as ``attach`` does.
    ``resolved`` is another parse of the same file whose asset paths are already absolute and confined.
    """
    _stand_in_assets(probe, resolved)
    probe.compiler.boundmass = max(probe.compiler.boundmass, MASS_FLOOR)
    probe.compiler.boundinertia = max(probe.compiler.boundinertia, MASS_FLOOR)
    try:
        # Its warnings are about stand-ins, or come again from the part's real compile: not shown.
        with installed_mujoco.collected():
            probe.compile()
    except ValueError as error:
        raise MjcfError(refusal_line(str(error), shown, lines, "MuJoCo refuses it")) from None


_COMPILE_WHERE = re.compile(r"Element name '(?P<name>[^']*)', id \d+(?:, line (?P<line>\d+))?")
_PARSE_WHERE = re.compile(r"Element '(?P<tag>[^']*)', line (?P<line>\d+)")
_REFERENCE = re.compile(
    r"not found|unknown|unrecognized (?:name|object)|missing transmission|must have valid"
)
"""Words of MuJoCo's messages about a name that points at nothing (or at nothing of the right kind)."""

REPAIR_HINT = " (a spec can declare a repair: mjcf_fixes)"


def same_lines(line: int) -> int | None:
    """The line map of a file MuJoCo read from disk itself (0: an included file, no line)."""
    return line or None


def _element_lines(text: bytes) -> list[int]:
    """The line of each element's start tag, in document order."""
    parser = xml.parsers.expat.ParserCreate()
    lines: list[int] = []
    parser.StartElementHandler = lambda *_: lines.append(parser.CurrentLineNumber)
    parser.Parse(text, True)
    return lines


def original_lines(root: ET.Element, text: bytes) -> dict[ET.Element, int]:
    """Each element of ``root`` (parsed from ``text``, not yet edited) -> its line in ``text``."""
    return dict(zip(root.iter(), _element_lines(text), strict=True))


def repaired_lines(root: ET.Element, repaired: str, original: dict[ET.Element, int]) -> LineMap:
    """The line map from the repaired text of ``root`` back to the file (see the module docstring).
    An element the repair created (e.g. a ``<compiler>``) has no line in the file."""
    by_line: dict[int, int | None] = {}
    for element, line in zip(root.iter(), _element_lines(repaired.encode()), strict=True):
        by_line.setdefault(line, original.get(element))
    return lambda line: by_line.get(line)


def _clean(text: str) -> str:
    message = " ".join(text.split())
    for prefix in ("XML Error: ", "Error: "):
        message = message.removeprefix(prefix)
    return message


def _hint(message: str) -> str:
    if "balanceinertia" in message:  # MuJoCo names its own knob; ours is a declared repair
        return (
            "correct the <inertial>, or declare the repair in the spec: mjcf_fixes: [{element: compiler, "
            "set: {balanceinertia: 'true'}, why: ...}]"
        )
    if _REFERENCE.search(message):
        return "correct the name or remove the element"
    return "correct the file"


def refusal_line(error: str, shown: str, lines: LineMap, refusal: str) -> str:
    """One line for MuJoCo's error text ``error`` about the file displayed as ``shown``:
    ``robot.xml:33: <refusal>: <MuJoCo's words> (element 'a1'); <what to do> (... mjcf_fixes)``.

    ``refusal`` says which step refused (reading or compiling); MuJoCo's own words are kept, so a
    reader can search for them.
    """
    where = _COMPILE_WHERE.search(error) or _PARSE_WHERE.search(error)
    text = error[: where.start()] if where else error
    message = _clean(text)
    located = shown
    if where is not None:
        line = lines(int(where.group("line") or 0))
        if line is not None:
            located = f"{shown}:{line}"
        name = where.groupdict().get("name")
        if name and f"'{name}'" not in message:
            message += f" (element '{name}')"
    hint = _hint(message)
    return f"{located}: {refusal}: {message}; {hint}{'' if 'mjcf_fixes' in hint else REPAIR_HINT}"
