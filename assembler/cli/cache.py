"""``assembler cache info|clear``: where the cache is, what each of its parts holds, and emptying
it (every part: :mod:`assembler.cache.folder`)."""

from __future__ import annotations

import argparse

from assembler.cache import cache_disabled
from assembler.cache.folder import LABELS
from assembler.cache.folder import info as folder_info
from assembler.cli.common import table
from assembler.compiler.service import clear, default_store
from assembler.errors import AssemblerError
from assembler.files.cache_location import DISABLE_VARIABLE, MAX_BYTES_VARIABLE, format_size, max_bytes
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
        files = sum(part.files for part in before.parts.values())
        print(
            f"removed {files} file{'s' if files != 1 else ''} ({format_size(before.total_bytes)}) "
            f"from {display_path(before.directory)}"
        )
        return 0
    info = store.info()
    if cache_disabled():
        status = f"disabled ({DISABLE_VARIABLE} is set)"
    else:
        status = f"unusable: {info.problem}" if info.problem else "enabled"
    whole = folder_info(store.directory)
    rows = [
        ("location", display_path(info.directory)),
        ("entries", str(info.entries)),
        *(
            (LABELS[part], f"{found.files} files ({format_size(found.total_bytes)})")
            for part, found in whole.parts.items()
        ),
        ("size", format_size(whole.total_bytes)),
        ("limit", f"{format_size(max_bytes())} ({MAX_BYTES_VARIABLE}), every part together"),
        ("status", status),
    ]
    print(table(rows))
    return 0
