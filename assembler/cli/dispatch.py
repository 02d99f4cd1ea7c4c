"""Running one parsed command: the user's spec folders and allowed paths first, then the command's
own module, imported now (``assembler --help`` never pays for it)."""

from __future__ import annotations

import argparse
import importlib

from assembler.files.paths import allowing
from assembler.registry.catalog import add_spec_folders


def run_command(args: argparse.Namespace) -> int:
    """Carry out the command ``args`` names and return its exit code."""
    with allowing(args.allow_path):
        add_spec_folders(args.specs)
        command = importlib.import_module(args.module)
        return int(command.run(args))
