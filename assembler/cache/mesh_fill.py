"""Fill the mesh store: decode mesh files with MuJoCo's decoder and keep the result.

:func:`main` (arguments ``STORE_DIR MAX_BYTES PATH KIND [PATH KIND ...]``) is the background
process :func:`assembler.cache.mesh_swap.store_meshes` starts after a compile that met new mesh
files; :func:`fill` is the same work in the calling process.

Each file is hashed again here (its record usually answers): the entry is stored under the digest
of the content that was decoded, and only if the file's stat is the same before hashing and after
decoding, with no change in the last seconds. A claim per entry keeps two processes from decoding
the same file at once. A file MuJoCo cannot decode is not stored (its compile reports it).
"""

from __future__ import annotations

import contextlib
import os
from collections.abc import Iterable
from pathlib import Path

from assembler.cache.file_state import settled
from assembler.cache.file_state import stat_of as file_stat
from assembler.cache.mesh_data import decode
from assembler.cache.meshes import MeshStore


def fill_one(store: MeshStore, path: str, kind: str) -> bool:
    """Decode and store one file unless stored already; True when this call stored it."""
    found = store.digest(path)
    if found is None or not settled(found[1]):
        return False
    digest, stat = found
    if store.has(kind, digest, stat[0]):
        return False
    claim = store.claim(kind, digest, stat[0])
    if claim is None:
        return False  # another process is decoding it
    try:
        if store.has(kind, digest, stat[0]):
            return False  # stored by the claim's previous holder between our two looks
        try:
            payload = decode(path)
        except ValueError:
            return False
        with contextlib.suppress(OSError):
            if file_stat(path) == stat:
                store.put(kind, digest, stat[0], payload or b"")
                return True
        return False
    finally:
        with contextlib.suppress(OSError):
            claim.unlink()


def fill(store: MeshStore, meshes: Iterable[tuple[str, str]]) -> int:
    """Store every (path, kind) not stored yet, then evict down to the bound; returns how many
    entries were written."""
    written = sum(fill_one(store, path, kind) for path, kind in meshes)
    if written:
        store.evict()
    return written


def main(arguments: list[str]) -> int:
    """The background process: lowered priority, every failure silent (nothing is stored)."""
    if len(arguments) < 2 or len(arguments) % 2:
        return 2
    with contextlib.suppress(AttributeError, OSError):
        os.nice(10)  # the user's next process matters more than filling the store
    store = MeshStore(Path(arguments[0]), int(arguments[1]))
    fill(store, zip(arguments[2::2], arguments[3::2], strict=True))
    return 0
