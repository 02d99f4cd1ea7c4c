"""MJCF text written for robosuite, which reads models from files: files named by their content in
the cache's ``robosuite/`` folder (:mod:`assembler.cache.content`), kept across processes and
verified on every use: a warm ``robosuite.make`` writes nothing, and a part file edited in the cache
is made again, never simulated. With the cache off they go to a folder of the process's own."""

from __future__ import annotations

import dataclasses
import json
from collections.abc import Callable, Iterable, Mapping

import mujoco

from assembler.cache.content import PARTS, content_folder, recorded_text_file, text_file
from assembler.cache.file_state import buffer_digest
from assembler.cache.key import FORMAT, code_fingerprint, resolution_environment


def written_file(text: str) -> str:
    """The path of a file holding ``text`` (written only when no whole one is there)."""
    return str(text_file(content_folder(PARTS), text, ".xml"))


def kept_file(
    inputs: object,
    read: Iterable[str],
    emit: Callable[[], str],
    read_earlier: Callable[[], Mapping[str, tuple[int, int]]] | None = None,
) -> str:
    """The part file of ``inputs`` (a part's or an assembly's build inputs, plain frozen data), kept
    across processes: found by a key of the inputs (and their kind), the assembler's code, MuJoCo's
    version and the resolution environment, and served without ``emit()`` while the files in
    ``read`` (its MJCF, includes and assets) are unchanged and the file is whole. ``read`` and
    ``read_earlier`` are used only when the text is made (see
    :func:`~assembler.cache.content.recorded_text_file`)."""
    material = {
        "format": FORMAT,
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "environment": resolution_environment(),
        "kind": type(inputs).__qualname__,
        "inputs": dataclasses.asdict(inputs) if dataclasses.is_dataclass(inputs) else repr(inputs),  # type: ignore[arg-type]
    }
    key = buffer_digest(json.dumps(material, sort_keys=True, default=repr).encode())
    return str(recorded_text_file(content_folder(PARTS), key, read, emit, ".xml", read_earlier))
