"""``assembler new MODEL_FILE``: write a first spec for a vendor's MJCF or URDF (every guess commented),
or for a MuJoCo Menagerie model by name (``menagerie:NAME[/ENTRY]``, :mod:`assembler.files.menagerie`)."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.errors import AssemblerError
from assembler.files import menagerie
from assembler.files.paths import display_path
from assembler.files.repositories import MARKER
from assembler.importers import write_new_spec
from assembler.importers.checking import build_problems
from assembler.importers.pack import importable, write_pack
from assembler.importers.packages import environment, found_packages


def run(args: argparse.Namespace) -> int:
    output = Path(args.output) if args.output else None
    model_file = Path(args.model_file)
    if args.model_file.startswith(menagerie.NEW_PREFIX):  # a Menagerie model by name
        model_file, served = menagerie.entry_file(args.model_file)
        print(f"{args.model_file}: {display_path(model_file)} ({served.license}, oid {served.oid[:12]})")
    if args.pack:
        return _pack(args, model_file)
    written, target = write_new_spec(model_file, output, args.kind, args.force, args.strict)
    # A package the user has still to declare is found for the check, as it will be once declared.
    pending = [package for package in written.packages if package.declared != "beside the spec"]
    with found_packages(pending):
        problems = build_problems(target, written.kind)
    print(f"wrote {display_path(target)}: {written.kind} {written.name}", end="")
    if len(pending) < len(written.packages):
        print(f" and {display_path(target.parent / MARKER)}", end="")
    if not _built_as_written(problems, " once the packages below are found" if pending else ""):
        return 1
    for package in pending:
        print(f"to do: {package.todo}")
    for name, value in environment(pending).items():
        print(f"  export {name}={value}")
    return 0


def _built_as_written(problems: list[str], found: str = "") -> bool:
    """End the 'wrote ...' line with whether the written spec builds (its problems on stderr)."""
    if problems:
        print("; it does not build as written:")
        for line in problems:
            print(line, file=sys.stderr)
        return False
    print(f" (validated and compiled{found}); check each 'guess:' and settle each 'decide:' comment")
    return True


def _pack(args: argparse.Namespace, model_file: Path) -> int:
    """``new --pack DIR``: the spec written into a pack with the vendor's files
    (:mod:`assembler.importers.pack`)."""
    if args.output:
        raise AssemblerError(
            "new: give -o SPEC or --pack DIR, not both (a pack's spec goes in DIR/<package>/specs)"
        )
    pack = Path(args.pack)
    written = write_pack(model_file, pack, args.kind, args.force, args.strict)
    with importable(pack.resolve()):  # the pack's package:// names resolve as once it is installed
        problems = build_problems(written.spec_path, written.spec.kind)
    print(
        f"wrote {display_path(written.spec_path)}: {written.spec.kind} {written.spec.name}, and "
        f"{written.copied} vendor files under {display_path(pack / written.package / 'assets')}",
        end="",
    )
    if written.pyproject_written:
        print(f" and {display_path(pack / 'pyproject.toml')}", end="")
    if not _built_as_written(problems):
        return 1
    if not written.licences:
        print(
            "decide: no licence file lies beside the vendor's files: add the licence you may share them "
            f"under to {display_path(pack / written.package / 'assets')}"
        )
    if not written.pyproject_written:
        print(
            f"to do: {display_path(pack / 'pyproject.toml')} exists and was kept; declare "
            f'[project.entry-points."robot_assembler.specs"] {written.package} = "{written.package}:specs"'
        )
    print(f"publish it: python -m build {display_path(pack)}, then pip install the wheel")
    return 0
