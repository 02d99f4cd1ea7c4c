"""``assembler build`` answered from the cache before any spec is read: a build made before with
the same flags, in the same environment, from unchanged spec files writes the XML the cache kept
(see :mod:`assembler.build.repeat`). This module imports the cache layer and nothing that reads
specs, so the command line tries it before the catalog is imported (``assembler.cli.main``).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path
from typing import Any

from assembler.build.repeat import KeyedRequest, answered_xml, keyed
from assembler.cache.settings import volatile_folders
from assembler.files.bundles import bundle_xml, write_model
from assembler.files.paths import allowing, display_path
from assembler.registry.arguments import spec_file_path


def robot_file(args: argparse.Namespace) -> Path | None:
    """The robot's spec file, when the command names one rather than a registered robot."""
    return spec_file_path(args.robot)


def build_request(args: argparse.Namespace) -> dict[str, Any] | None:
    """The request a ``build`` command line makes (every flag that decides the XML, as given), or
    None with ``--no-cache``."""
    if getattr(args, "no_cache", False):
        return None
    spec_file = robot_file(args)
    return {
        "kind": "build",
        "robot": str(spec_file) if spec_file is not None else args.robot,
        "idn": args.idn,
        "base": args.base,
        "no_base": args.no_base,
        "gripper": list(args.gripper),
        "no_grippers": args.no_grippers,
        "set": list(args.overrides),
        "specs": [str(Path(folder).resolve()) for folder in args.specs],
        "allow_path": [str(Path(folder).resolve()) for folder in args.allow_path],
    }


def request_of(args: argparse.Namespace) -> KeyedRequest | None:
    """The request of a ``build`` command line: the one :func:`answer` made, or made now."""
    made: KeyedRequest | None = getattr(args, "request", None)
    if made is not None:
        return made
    plain = build_request(args)
    return None if plain is None else keyed(plain)


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
    plain = build_request(args)
    if plain is None or args.target != "mujoco":  # an engine's check needs the model itself
        return None
    request = args.request = keyed(plain)
    with allowing(args.allow_path):  # as the full command runs: the allowed folders are in the key
        found = answered_xml(request)
    if found is None:
        return None
    xml, record = found
    write_xml(args, xml, record.name)
    for note in record.notes:
        print(note, file=sys.stderr)
    return 0
