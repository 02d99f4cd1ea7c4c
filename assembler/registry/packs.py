"""Spec packs: robots, bases, grippers and motors that other distributions install.

A distribution declares an entry point in the group ``robot_assembler.specs`` whose value names an
importable package holding specs and their assets, the package itself or a folder in it::

    [project.entry-points."robot_assembler.specs"]
    acme = "acme_robots"          # every spec under acme_robots/
    # acme = "acme_robots:specs"  # or only those under acme_robots/specs/

Its names join the shipped ones: registered by name when the catalog loads, each spec read on
first lookup (:mod:`assembler.registry.shipped`), read as any installed package's files are. Two
sources of one name (two packs, or a pack and the shipped specs) are an error at that name's
lookup naming both, never a silent winner; a spec of one of those names in a lab's own folders is
refused naming the pack's file, as for a shipped name.
"""

from __future__ import annotations

import importlib.metadata
import importlib.util
import warnings
from dataclasses import dataclass
from pathlib import Path

from assembler.errors import AssemblerWarning

GROUP = "robot_assembler.specs"


@dataclass(frozen=True)
class Pack:
    """One installed pack: where its specs are and which distribution installed them."""

    name: str
    """The entry point's name (``acme``)."""
    distribution: str
    """The installed distribution declaring it (``acme-robots``)."""
    version: str
    """That distribution's version."""
    folder: Path
    """The folder of specs (resolved)."""

    @property
    def label(self) -> str:
        """How messages and ``assembler list`` name it: ``pack acme-robots 1.0``."""
        return f"pack {self.distribution} {self.version}"


def _folder(value: str) -> Path | None:
    """The folder an entry point's value names: ``package`` or ``package:sub/folder``."""
    package, _, inside = value.partition(":")
    try:
        found = importlib.util.find_spec(package.strip())
    except (ImportError, ValueError):
        return None
    locations = list(found.submodule_search_locations or []) if found is not None else []
    if not locations:
        return None
    folder = Path(locations[0]) / inside.strip() if inside.strip() else Path(locations[0])
    return folder.resolve() if folder.is_dir() else None


def installed_packs() -> list[Pack]:
    """Every installed pack, in a stable order (by entry point name, then distribution); an entry
    point naming no folder is said once as a warning and skipped."""
    packs: list[Pack] = []
    for entry in importlib.metadata.entry_points(group=GROUP):
        distribution = entry.dist.name if entry.dist is not None else "?"
        version = entry.dist.version if entry.dist is not None else "?"
        folder = _folder(entry.value)
        if folder is None:
            warnings.warn(
                f"spec pack {entry.name} ({distribution} {version}): {entry.value!r} names no folder of an "
                "importable package; its robots are not available (reinstall it, or fix its entry point)",
                AssemblerWarning,
                stacklevel=2,
            )
            continue
        packs.append(Pack(entry.name, distribution, version, folder))
    return sorted(packs, key=lambda pack: (pack.name, pack.distribution))


def pack_of(path: Path) -> Pack | None:
    """The installed pack whose folder holds ``path``, if any."""
    resolved = path.resolve()
    return next((pack for pack in installed_packs() if resolved.is_relative_to(pack.folder)), None)
