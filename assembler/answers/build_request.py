"""The request an ``assembler build`` makes, from plain values, and its answer from the cache.

The command line passes its flags in (:class:`BuildFlags`); nothing here knows argparse. A build
made before with the same flags, in the same environment, from unchanged spec files is answered
with the XML the cache kept (:func:`cached_xml`), before any spec is read: this module imports the
cache layer and nothing that reads specs.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from assembler.answers.records import KeyedRequest, answered_xml, keyed
from assembler.cache.requests import RequestRecord
from assembler.files.paths import allowing
from assembler.spec.part_arguments import spec_file_path


@dataclass(frozen=True)
class BuildFlags:
    """Every flag of ``assembler build`` that decides the XML it writes, as given."""

    robot: str
    """A registered robot's name or a spec file."""
    idn: int | str
    """The robot's idn (its names' prefix)."""
    base: str | None
    """``--base``: a base's name or spec file, or None for the robot's default."""
    no_base: bool
    """``--no-base``."""
    grippers: Sequence[str]
    """``--gripper ARM=NAME`` values, in order."""
    no_grippers: bool
    """``--no-grippers``."""
    overrides: Sequence[str]
    """``--set PATH=VALUE`` values, in order."""
    specs: Sequence[str]
    """``--specs`` folders, in order."""
    allow_path: Sequence[str]
    """``--allow-path`` folders, in order."""

    @property
    def robot_file(self) -> Path | None:
        """The robot's spec file, when the flags name one rather than a registered robot."""
        return spec_file_path(self.robot)


def build_request(flags: BuildFlags) -> dict[str, Any]:
    """The request ``flags`` make: plain JSON data, the spec file and folders resolved."""
    spec_file = flags.robot_file
    return {
        "kind": "build",
        "robot": str(spec_file) if spec_file is not None else flags.robot,
        "idn": flags.idn,
        "base": flags.base,
        "no_base": flags.no_base,
        "gripper": list(flags.grippers),
        "no_grippers": flags.no_grippers,
        "set": list(flags.overrides),
        "specs": [str(Path(folder).resolve()) for folder in flags.specs],
        "allow_path": [str(Path(folder).resolve()) for folder in flags.allow_path],
    }


def keyed_build(flags: BuildFlags) -> KeyedRequest:
    """The request ``flags`` make, with its record's key."""
    return keyed(build_request(flags))


def cached_xml(request: KeyedRequest, allow_path: Sequence[str]) -> tuple[str, RequestRecord] | None:
    """The XML a build made before wrote for ``request`` and its record, or None when the cache cannot
    answer. The allowed folders are in force while the record's files are checked, as they are for
    the full command (they are in the key)."""
    with allowing(allow_path):
        return answered_xml(request)
