"""The shipped specs: registered by name at import, each read and validated when its name is first
looked up.

Why: reading and validating all 63 shipped specs costs about 0.2 s, more than any one robot needs;
``assemble("Panda")`` reads three (the robot, its base, its gripper). So the catalog registers each
shipped name with the file that defines it (:class:`ShippedIndex`, a :class:`Unmade` of the
registries) and the file is loaded the first time its name is looked up, by exactly the path that
loads a user's spec file (:func:`assembler.registry.catalog.register_specs`), with every check. A
spec that extends another looks its parent up the same way. Anything that reads a whole table (a
listing, robosuite's bridge, a duplicate check against every name) loads the rest first, in one batch.

The index is a scan of each file's top-level ``name:`` and ``kind:`` lines, not YAML: a file the
scan cannot read plainly (no such line, a name twice, an unknown kind, a link out of the folder)
makes the whole folder load at import as before, so its problem is reported as before.

Holding the names imports neither the model classes nor the schema (the catalog, which reads specs,
is imported when a name is first made): robosuite's bridge holds them at every import, and a warm
``robosuite.make`` of recorded parts never makes one.
"""

from __future__ import annotations

import importlib
import re
import threading
from collections.abc import Callable, Sequence
from pathlib import Path
from typing import Any

from assembler.errors import Problem, RegistryError
from assembler.files.paths import display_path, shipped_specs_dir
from assembler.models.registering import REGISTRIES
from assembler.registry import packs
from assembler.spec.part_arguments import spec_files

PART_KINDS = ("robot", "base", "gripper")
"""The spec kinds that are registered parts (a scene or an experiment in the folder is neither)."""

_NOT_PARTS = ("scene", "experiment", "motor")
"""Kinds of spec in the folder that are no registered part: motors are read by the motor table
(:mod:`assembler.models.motor_table`) when one is first looked up."""

_NAME = re.compile(r"""^name:[ \t]*(['"]?)([A-Za-z_][\w.-]*)\1[ \t]*(?:#.*)?$""", re.MULTILINE)
_KIND = re.compile(r"""^kind:[ \t]*(['"]?)(\w+)\1[ \t]*(?:#.*)?$""", re.MULTILINE)


def _scanned(file: Path, folder: Path) -> tuple[str, str] | None:
    """(kind, name) of a part spec file; ("", "") for a scene, experiment or motor; None if unclear."""
    try:
        if not file.resolve().is_relative_to(folder):
            return None
        text = file.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError, RuntimeError):
        return None
    names, kinds = _NAME.findall(text), _KIND.findall(text)
    kind = kinds[0][1] if len(kinds) == 1 else "robot" if not kinds else ""
    if kind in _NOT_PARTS:
        return ("", "")
    if len(names) != 1 or kind not in PART_KINDS:
        return None
    return kind, names[0][1]


def scan(folder: Path) -> dict[tuple[str, str], Path] | None:
    """Each part spec's (kind, name) and its file; None if any file is unclear (see the module)."""
    resolved = folder.resolve()
    files: dict[tuple[str, str], Path] = {}
    for file in spec_files(folder):
        found = _scanned(file, resolved)
        if found is None or found in files:
            return None
        if found != ("", ""):
            files[found] = file
    return files


def motor_files(folder: Path) -> list[Path]:
    """The motor spec files of a folder (``kind: motor``), which a part of it may name."""
    found = []
    for file in spec_files(folder):
        try:
            kinds = _KIND.findall(file.read_text(encoding="utf-8"))
        except (OSError, UnicodeDecodeError):
            continue
        if [kind for _, kind in kinds] == ["motor"]:
            found.append(file)
    return found


class ShippedIndex:
    """The shipped names whose specs are not read yet, and the one way to read them.

    Thread-safe: a name being made counts as held, so another thread's lookup of it waits for the
    class instead of finding neither the name nor the class (the lock is re-entrant: making a spec
    looks up its own name and its parent's)."""

    def __init__(
        self,
        files: dict[tuple[str, str], Path],
        register: Callable[[Sequence[Path]], list[Any]],
        conflicts: dict[tuple[str, str], list[str]] | None = None,
    ):
        self.files = files
        """(family, name) -> the spec file, for each name not made yet."""
        self.register = register
        """Validates and registers spec files, all or nothing (the catalog's ``register_specs``)."""
        self.conflicts = conflicts or {}
        """(family, name) -> the sources that each define it (two packs, a pack and the shipped
        specs): looking it up is an error naming them."""
        self._making: set[tuple[str, str]] = set()
        self._lock = threading.RLock()

    def holds(self, family: str, name: str) -> bool:
        key = (family, name)
        return key in self.files or key in self._making or key in self.conflicts

    def _refuse(self, keys: Sequence[tuple[str, str]]) -> None:
        problems = [
            Problem(
                f"{family} '{name}' is defined by {' and by '.join(self.conflicts[(family, name)])}; "
                "uninstall one of them, or ask its authors to rename theirs"
            )
            for family, name in keys
        ]
        if problems:
            raise RegistryError(problems)

    def make(self, family: str, name: str) -> None:
        self._refuse([key for key in [(family, name)] if key in self.conflicts])
        with self._lock:
            file = self.files.pop((family, name), None)
            if file is None:  # made meanwhile by another thread, or being made by this one
                return
            made = self._registered({(family, name): file})
            if name not in {cls.__name__ for cls in made}:  # the scan misread the file: read them all
                self.make_all()

    def make_all(self) -> None:
        self._refuse(sorted(self.conflicts))
        with self._lock:
            held = dict(self.files)
            self.files.clear()
            if held:
                self._registered(held)

    def _registered(self, held: dict[tuple[str, str], Path]) -> list[Any]:
        """Register the files of ``held``; on failure they are held again (the next lookup reports
        the same problem)."""
        self._making.update(held)
        try:
            return self.register(list(held.values()))
        except BaseException:
            self.files.update(held)
            raise
        finally:
            self._making.difference_update(held)

    def held(self, family: str) -> list[str]:
        with self._lock:  # not while another thread is making names: those are about to be made
            return [name for held_family, name in self.files if held_family == family]

    def state(self) -> object:
        return dict(self.files)

    def restore(self, state: object) -> None:
        assert isinstance(state, dict)
        self.files.clear()
        self.files.update(state)


def _catalog() -> Any:
    """The catalog, which reads and registers spec files (the schema with it): imported when a held
    name is first made, or a folder cannot be held by name."""
    return importlib.import_module("assembler.registry.catalog")


def _register_specs(paths: Sequence[Path]) -> list[Any]:
    return _catalog().register_specs(*paths)  # type: ignore[no-any-return]


_held = False


def hold_shipped_names() -> None:
    """Register each shipped name and each installed pack's (:mod:`assembler.registry.packs`) with
    its file, read on first lookup; a folder that cannot be indexed plainly is read now (see the
    module). A name two sources define is held as a conflict. Once per process: the catalog calls it
    as it loads, and robosuite's bridge without loading it."""
    global _held
    if _held:
        return
    _held = True
    installed = packs.installed_packs()
    sources = [("the shipped specs", shipped_specs_dir())]
    sources += [(f"{pack.label} ({pack.name})", pack.folder) for pack in installed]
    pack_motors = [file for pack in installed for file in motor_files(pack.folder)]
    if pack_motors:  # few and small; a pack's part may name them, and motors have no lazy index
        _register_specs(pack_motors)
    files: dict[tuple[str, str], Path] = {}
    defined: dict[tuple[str, str], list[str]] = {}
    for label, folder in sources:
        if not folder.is_dir():
            continue
        found = scan(folder)
        if found is None:
            _register_specs([folder])
            continue
        for key, file in found.items():
            files.setdefault(key, file)
            defined.setdefault(key, []).append(f"{label}: {display_path(file)}")
    conflicts = {key: places for key, places in defined.items() if len(places) > 1}
    for key in conflicts:
        files.pop(key)
    index = ShippedIndex(files, _register_specs, conflicts)
    for table in REGISTRIES.values():
        table.unmade = index
