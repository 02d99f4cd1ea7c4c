"""MJCF files from strangers, checked before ElementTree or MuJoCo parses them.

A spec's MJCF may come from a pull request, so before any full parser sees it we check, with a
streaming pass of expat that builds nothing:

- its size (:data:`assembler.files.limits.MAX_MJCF_BYTES`);
- that it has no document type declaration: a DTD is where XML entities are declared, and both
  entity expansion ("billion laughs") and external entities (which read other local files) start
  there. MJCF never needs one;
- that every file it pulls in while parsing (``<include file>``, ``<model file>``) stays in the
  allowed folders and passes the same checks, to :data:`assembler.files.limits.MAX_MJCF_INCLUDE_DEPTH`.

Meshes and textures are read later, at compile time; :mod:`assembler.mjcf.source` confines them.
"""

from __future__ import annotations

import xml.parsers.expat
from collections.abc import Collection
from pathlib import Path

from assembler.errors import MjcfError
from assembler.files.inputs import note_inputs
from assembler.files.limits import MAX_MJCF_BYTES, MAX_MJCF_INCLUDE_DEPTH
from assembler.files.paths import confine, display_path
from assembler.files.regular import not_regular, open_regular

FILE_ELEMENTS: tuple[str, ...] = ("include", "model", "flexcomp")
"""Elements whose ``file`` MuJoCo reads while parsing the XML (meshes and textures are read at
compile time and checked after parsing)."""

DIRECTORY_ATTRIBUTES: tuple[str, ...] = ("meshdir", "assetdir")
"""``<compiler>`` folders a parse-time file (a flexcomp's mesh) may be taken relative to."""


class _Refused(Exception):
    """Raised inside an expat handler to stop the parse at once."""


def _read(path: Path) -> bytes:
    shown = display_path(path)
    try:
        with open_regular(path) as stream:
            data = stream.read(MAX_MJCF_BYTES + 1)
    except OSError as error:
        raise MjcfError(f"{shown}: cannot read the file: {error.strerror}") from None
    if len(data) > MAX_MJCF_BYTES:
        raise MjcfError(f"{shown}: the file's size exceeds the limit of {MAX_MJCF_BYTES} bytes for MJCF")
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
