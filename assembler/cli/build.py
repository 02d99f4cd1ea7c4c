"""Building and the cache: ``assembler build`` writes a robot's standalone MJCF (to a file, a bundle
folder or stdout) and records the request, so the same build next time is answered before any spec
is read (:mod:`assembler.cli.cached_build`, kept apart: it must load without the spec layer);
``assembler cache info|clear`` says where the cache is and what each of its parts holds, and empties
it (every part: :mod:`assembler.cache.folder`)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.answers.request import record_answer
from assembler.cache import cache_disabled
from assembler.cache.folder import LABELS
from assembler.cache.folder import info as folder_info
from assembler.cli.cached_build import build_flags, request_of, write_xml
from assembler.cli.common import assembled, idle_override_warnings, part_alone, table, use_cache
from assembler.compiler.service import clear, default_store
from assembler.errors import AssemblerError
from assembler.files.cache_location import DISABLE_VARIABLE, MAX_BYTES_VARIABLE, format_size, max_bytes
from assembler.files.paths import display_path
from assembler.gpu.put_model_check import check_with_mujoco_warp


def _part_alone(args: argparse.Namespace) -> bool:
    """Write the MJCF of a gripper or base spec built alone (``assembler build hand.yaml``), if
    ``args.robot`` names one and no robot; return whether it did."""
    part = part_alone(args)
    if part is None:
        return False
    _, spec = part.compile_alone_spec()
    write_xml(args, spec.to_xml(), type(part).__name__)
    return True


def run_build(args: argparse.Namespace) -> int:
    if _part_alone(args):
        return 0
    robot = assembled(args)
    xml = robot.get_xml(cache=use_cache(args))  # compiled first: a robot that does not compile writes nothing
    notes = idle_override_warnings(args)  # every --set checked before anything is written
    if args.target == "mjwarp":  # before writing: a model MuJoCo Warp refuses writes nothing either
        print(
            check_with_mujoco_warp(robot.get_model(cache=use_cache(args)), type(robot).__name__),
            file=sys.stderr,
        )
    write_xml(args, xml, type(robot).__name__)
    for note in notes:
        print(note, file=sys.stderr)
    request = request_of(args)
    if request is not None:
        record_answer(
            request, robot, [Path(folder) for folder in args.specs], build_flags(args).robot_file, notes
        )
    return 0


def run_cache(args: argparse.Namespace) -> int:
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
