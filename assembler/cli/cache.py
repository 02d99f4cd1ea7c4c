"""``assembler cache info|clear``: where the compiled-model cache is, how full, and emptying it."""

from __future__ import annotations

import argparse

from assembler.build.service import clear, default_store
from assembler.cache import cache_disabled
from assembler.cache.meshes import default_mesh_store
from assembler.cache.settings import DISABLE_VARIABLE, MAX_BYTES_VARIABLE, format_size, max_bytes
from assembler.cli.common import table
from assembler.errors import AssemblerError
from assembler.files.paths import display_path


def run(args: argparse.Namespace) -> int:
    store = default_store()
    if args.action == "clear":
        before = clear(store)
        if before.not_removed:
            raise AssemblerError(
                f"could not remove {len(before.not_removed)} file(s) from {display_path(before.directory)}; "
                f"first: {before.not_removed[0]}"
            )
        print(
            f"removed {before.entries} {'entry' if before.entries == 1 else 'entries'} "
            f"({format_size(before.total_bytes)}) "
            f"from {display_path(before.directory)}"
        )
        return 0
    info = store.info()
    if cache_disabled():
        status = f"disabled ({DISABLE_VARIABLE} is set)"
    else:
        status = f"unusable: {info.problem}" if info.problem else "enabled"
    meshes = default_mesh_store()
    mesh_info = meshes.info() if meshes is not None else None
    rows = [
        ("location", display_path(info.directory)),
        ("entries", str(info.entries)),
        ("size", format_size(info.total_bytes)),
        (
            "meshes",
            f"{mesh_info.entries} decoded ({format_size(mesh_info.total_bytes)})" if mesh_info else "-",
        ),
        ("limit", f"{format_size(max_bytes())} ({MAX_BYTES_VARIABLE}), models and meshes together"),
        ("status", status),
    ]
    print(table(rows))
    return 0
