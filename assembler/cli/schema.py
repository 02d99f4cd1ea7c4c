"""``assembler schema``: the JSON Schema of every spec kind, for editors and review bots, or (with
``--markdown``) the spec reference generated from it (``docs/spec.md``)."""

from __future__ import annotations

import argparse
import sys

from assembler.schema.json_schema import schema_text


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("schema", help="print the JSON Schema of spec files (or --markdown docs)")
    parser.add_argument(
        "--markdown", action="store_true", help="print the spec reference (docs/spec.md) instead"
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    sys.stdout.write(schema_text(markdown=args.markdown))
    return 0
