"""MJCF text written for robosuite, which reads models from files: files named by their content in
the cache's ``robosuite/`` folder (:mod:`assembler.cache.content`), kept across processes and
verified on every use. Every hard reset of an environment rebuilds every model, and the text of an
unchanged part does not change: a warm ``robosuite.make`` builds no part, emits and writes nothing,
and a part file edited in the cache is made again, never simulated. With the cache off they go to a
folder of the process's own.

What the emission warned (an :class:`~assembler.errors.AssemblerWarning`: grip frames added, bodies
robosuite's world weighs differently) travels in the file as leading comments and is said again
wherever the file is used, once per process, so a warm make says what a cold one said."""

from __future__ import annotations

import dataclasses
import json
import warnings
from collections.abc import Callable, Iterable, Iterator, Mapping
from typing import Any
from xml.sax.saxutils import escape, unescape

import mujoco

from assembler import models
from assembler.cache.content import PARTS, content_folder, recorded_text_file, text_file
from assembler.cache.dependencies import asset_files
from assembler.cache.file_state import buffer_digest
from assembler.cache.key import FORMAT, code_fingerprint, resolution_environment
from assembler.errors import AssemblerWarning
from assembler.robosuite.lossless import lossless_xml

NOTE = "<!-- assembler says: "
"""How a part file carries a warning of its emission (one JSON object per leading comment line)."""

_DASH = {"-": "&#45;"}
"""A comment cannot hold ``--``: notes are written with every dash as a character reference."""

_SAID: set[tuple[str, str, int]] = set()
"""The notes said in this process, each once (not Python's registry for ``warn_explicit``: the
emission's own ``catch_warnings`` clears that registry, and a cold make would say a note again at
each part file it makes)."""


def written_file(text: str) -> str:
    """The path of a file holding ``text`` (written only when no whole one is there)."""
    return str(text_file(content_folder(PARTS), text, ".xml"))


def file_key(inputs: object) -> str:
    """The key a part file of ``inputs`` (a part's or an assembly's build inputs, plain frozen data)
    is kept under: a digest of the inputs (and their kind), the assembler's code, MuJoCo's version
    and the resolution environment."""
    material = {
        "format": FORMAT,
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "environment": resolution_environment(),
        "kind": type(inputs).__qualname__,
        "inputs": dataclasses.asdict(inputs) if dataclasses.is_dataclass(inputs) else repr(inputs),  # type: ignore[arg-type]
    }
    return buffer_digest(json.dumps(material, sort_keys=True, default=repr).encode())


def kept_file(
    inputs: object,
    read: Iterable[str],
    emit: Callable[[], str],
    read_earlier: Callable[[], Mapping[str, tuple[int, int]]] | None = None,
) -> str:
    """The part file of ``inputs``, kept across processes under :func:`file_key` and served without
    ``emit()`` while the files in ``read`` (its MJCF, includes and assets) are unchanged and the file
    is whole. ``read`` and ``read_earlier`` are used only when the text is made (see
    :func:`~assembler.cache.content.recorded_text_file`)."""
    return str(recorded_text_file(content_folder(PARTS), file_key(inputs), read, emit, ".xml", read_earlier))


def recorded_file(
    key: str,
    parts: Callable[[], list[models.PartModel]],
    build: Callable[[list[models.PartModel]], mujoco.MjSpec],
) -> str:
    """The part file kept under ``key`` (the :func:`file_key` of ``parts()``' inputs, from a make
    record), its notes said: served while its record is current, without ``parts()`` (which makes
    the parts: reads their specs); else made of them as :func:`robosuite_file` makes it."""
    made: list[list[models.PartModel]] = []

    def got() -> list[models.PartModel]:
        if not made:
            made.append(parts())
        return made[0]

    def read() -> Iterator[str]:  # iterated only on a miss
        yield from _files_read(got())

    path = str(
        recorded_text_file(
            content_folder(PARTS),
            key,
            read(),
            lambda: _emitted(lambda: build(got())),
            ".xml",
            lambda: _read_earlier(got()),
        )
    )
    say_notes(path)
    return path


def recorded_part_file(key: str, part: Callable[[], models.PartModel]) -> str:
    """The file robosuite reads for the part ``part()`` makes alone, from the key a make record
    holds: ``part()`` is called only when no file is kept under ``key``."""
    return recorded_file(key, lambda: [part()], lambda parts: parts[0].part_mjspec())


def recorded_assembly_file(
    key: str, robot: Callable[[], models.RobotModel], world: Callable[[models.RobotModel], mujoco.MjSpec]
) -> str:
    """The file robosuite reads for the robot ``robot()`` makes, with its base and grippers, from
    the key a make record holds: ``robot()`` and ``world`` (its assembly, checked for robosuite's
    world) are called only when no file is kept under ``key``."""

    def parts() -> list[models.PartModel]:
        made = robot()
        return [made, *made.models]

    return recorded_file(key, parts, lambda parts: world(robot()))


def robosuite_file(
    inputs: object, kept: bool, parts: list[models.PartModel], build: Callable[[], mujoco.MjSpec]
) -> str:
    """The lossless file of ``build()`` (the spec of ``parts``: one part, or an assembly), made only
    when no kept file of ``inputs`` is current (``kept`` False: a hand-written class, made every
    time); its notes said."""

    def emit() -> str:
        return _emitted(build)

    if kept:
        path = kept_file(inputs, _files_read(parts), emit, lambda: _read_earlier(parts))
    else:
        path = written_file(emit())
    say_notes(path)
    return path


def _emitted(build: Callable[[], mujoco.MjSpec]) -> str:
    """The lossless text of ``build()``, with what building and emitting it warned as leading notes."""
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        text = lossless_xml(build())
    notes = []
    for warning in caught:
        if issubclass(warning.category, AssemblerWarning):
            notes.append({"message": str(warning.message), "file": warning.filename, "line": warning.lineno})
        else:  # not ours to carry: said here only
            warnings.warn_explicit(warning.message, warning.category, warning.filename, warning.lineno)
    return "".join(f"{NOTE}{escape(json.dumps(note), _DASH)} -->\n" for note in notes) + text


def say_notes(path: str) -> None:
    """Say the notes a part file carries (what its emission warned), each once per process."""
    for note in _notes_of(path):
        said = (note["message"], note["file"], note["line"])
        if said not in _SAID:
            _SAID.add(said)
            warnings.warn_explicit(*said[:1], AssemblerWarning, *said[1:])


def _files_read(parts: list[models.PartModel]) -> Iterator[str]:
    """Every file the text of ``parts`` depends on: each part's MJCF and includes, and the asset files
    its text names (which must still be there). Lazy: a part's MJCF is read only when iterated."""
    for part in parts:
        yield from (path for path, _, _ in part.source.files)
        yield from asset_files(part.prepared_mjspec)


def _read_earlier(parts: list[models.PartModel]) -> dict[str, tuple[int, int]]:
    """Each part's MJCF and includes with their (size, mtime_ns) when the part read them."""
    return {path: (size, mtime) for part in parts for path, size, mtime in part.source.files}


def _notes_of(path: str) -> list[dict[str, Any]]:
    """The notes at the head of a part file."""
    notes = []
    with open(path, encoding="utf-8") as file:
        for line in file:
            if not line.startswith(NOTE):
                break
            note = line.removeprefix(NOTE).removesuffix(" -->\n")
            notes.append(json.loads(unescape(note, {v: k for k, v in _DASH.items()})))
    return notes
