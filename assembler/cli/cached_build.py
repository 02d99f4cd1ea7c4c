"""``assembler build`` answered from the cache before any spec is read (see
:mod:`assembler.answers.build_request`): this module turns the command line into plain values,
asks the answer path, and writes what it answers. It imports the cache layer and nothing that
reads specs, so the command line tries it before the commands load (``assembler.cli.main``).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.answers.build_request import BuildFlags, cached_xml, keyed_build
from assembler.answers.records import KeyedRequest
from assembler.files.bundles import bundle_xml, write_model
from assembler.files.cache_location import volatile_folders
from assembler.files.paths import display_path


def build_flags(args: argparse.Namespace) -> BuildFlags:
    """The flags of a ``build`` command line that decide its XML, as plain values."""
    return BuildFlags(
        robot=args.robot,
        idn=args.idn,
        base=args.base,
        no_base=args.no_base,
        grippers=tuple(args.gripper),
        no_grippers=args.no_grippers,
        overrides=tuple(args.overrides),
        specs=tuple(args.specs),
        allow_path=tuple(args.allow_path),
    )


def request_of(args: argparse.Namespace) -> KeyedRequest | None:
    """The request of a ``build`` command line (the one :func:`answer` made, or made now), or None
    with ``--no-cache``."""
    made: KeyedRequest | None = getattr(args, "request", None)
    if made is not None or getattr(args, "no_cache", False):
        return made
    return keyed_build(build_flags(args))


def write_xml(args: argparse.Namespace, xml: str, default_name: str) -> None:
    """Write ``xml`` where the flags say: a bundle folder, a file, or standard output."""
    if args.bundle:
        name = Path(args.output).name if args.output else f"{default_name}.xml"
        target = bundle_xml(xml, Path(args.bundle), name)
        print(f"wrote {display_path(target)} with its assets", file=sys.stderr)
    elif args.output:
        target, copied = write_model(xml, Path(args.output), volatile_folders())
        plural = "s" if copied != 1 else ""
        kept = f" and {copied} cached asset{plural} it names in {display_path(target)}-assets"
        print(f"wrote {display_path(target)}{kept if copied else ''}", file=sys.stderr)
    else:
        sys.stdout.write(xml)


def answer(args: argparse.Namespace) -> int | None:
    """Carry out ``build`` from the cache and return its exit code, or None when the cache cannot
    answer (the full command runs then, and records ``args.request``, the request made here)."""
    if getattr(args, "no_cache", False) or args.target != "mujoco":  # an engine's check needs the model
        return None
    request = args.request = keyed_build(build_flags(args))
    found = cached_xml(request, args.allow_path)
    if found is None:
        return None
    xml, record = found
    write_xml(args, xml, record.name)
    for note in record.notes:
        print(note, file=sys.stderr)
    return 0
