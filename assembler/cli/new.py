"""``assembler new MODEL_FILE``: write a first spec for a vendor's MJCF or URDF (every guess commented),
or for a MuJoCo Menagerie model by name (``menagerie:NAME[/ENTRY]``, :mod:`assembler.files.menagerie`)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.files import menagerie
from assembler.files.paths import display_path
from assembler.files.repositories import MARKER
from assembler.importers import write_new_spec
from assembler.importers.checking import build_problems
from assembler.importers.packages import environment, found_packages


def run(args: argparse.Namespace) -> int:
    output = Path(args.output) if args.output else None
    model_file = Path(args.model_file)
    if args.model_file.startswith(menagerie.NEW_PREFIX):  # a Menagerie model by name
        model_file, served = menagerie.entry_file(args.model_file)
        print(f"{args.model_file}: {display_path(model_file)} ({served.license}, oid {served.oid[:12]})")
    written, target = write_new_spec(model_file, output, args.kind, args.force, args.strict)
    # A package the user has still to declare is found for the check, as it will be once declared.
    pending = [package for package in written.packages if package.declared != "beside the spec"]
    with found_packages(pending):
        problems = build_problems(target, written.kind)
    print(f"wrote {display_path(target)}: {written.kind} {written.name}", end="")
    if len(pending) < len(written.packages):
        print(f" and {display_path(target.parent / MARKER)}", end="")
    if problems:
        print("; it does not build as written:")
        for line in problems:
            print(line, file=sys.stderr)
        return 1
    found = " once the packages below are found" if pending else ""
    print(f" (validated and compiled{found}); check each 'guess:' and settle each 'decide:' comment")
    for package in pending:
        print(f"to do: {package.todo}")
    for name, value in environment(pending).items():
        print(f"  export {name}={value}")
    return 0
