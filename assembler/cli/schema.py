"""``assembler schema``: the JSON Schema of every spec kind, for editors and review bots, or (with
``--markdown``) the spec reference generated from it (``docs/spec.md``)."""

from __future__ import annotations

import argparse
import sys

from assembler.spec.schema.json_schema import schema_text


def run(args: argparse.Namespace) -> int:
    sys.stdout.write(schema_text(markdown=args.markdown))
    return 0
