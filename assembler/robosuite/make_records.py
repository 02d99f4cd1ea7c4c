"""Make records: what robosuite reads of a part of ours at ``make``, kept in the cache, so that a
process whose specs did not change makes an environment without reading one.

Why: a warm ``robosuite.make("Lift", robots="Panda")`` read the robot's, gripper's and base's specs
and parsed their MJCF (to make our parts, whose names, poses and offsets robosuite reads), though
the files robosuite then reads were kept (:mod:`.files`): about 0.3 s of CPU of a 2.5 s make and ten
steps. What robosuite reads of a part (the values in :mod:`.robot_class` and :mod:`.part_classes`,
and the key of its kept file) are plain values, so the first process that makes a part for robosuite
records them (:func:`recorded_facts`) beside robosuite's part files, in the cache's verified store
(:func:`~assembler.cache.content.recorded_text_file`): keyed by what the part is (its family, name,
idn, spec file, and what was added to a robot), the assembler's code, MuJoCo's version and the
resolution environment, and served while every file they were made from (the spec, its parents, its
motors' specs, the MJCF and its includes) is unchanged. Only a shipped spec's classes keep
records (:func:`spec_file`): a robosuite class installed from its registration record
(:class:`~assembler.robosuite.registrations.SpecClassOf`, spec not read) reads its part's values
from the record, and anything else asked of it (its ``assembly`` or ``part``) makes the part then,
with what robosuite gave it, as a cold make would have; a user's class or an experiment's variant
is made as before. A miss or a changed file makes the part as before, and records it; with the
cache off nothing is recorded. robosuite still imports the schema with the bridge: reading no spec
at make is what this saves (a process free of the schema needs the registry's index and the
expression evaluator below it first).
"""

from __future__ import annotations

import inspect
import json
from collections.abc import Callable, Iterable, Iterator, Mapping
from pathlib import Path
from typing import Any

import mujoco

from assembler import models
from assembler.answers.records import Origin
from assembler.cache.content import PARTS, content_folder, recorded_text_file
from assembler.cache.file_state import buffer_digest
from assembler.cache.key import code_fingerprint, resolution_environment
from assembler.files.cache_location import cache_disabled
from assembler.models.registering import REGISTRIES

FORMAT = 1
"""Version of a record's contents and key; bump it when either changes."""

Facts = dict[str, Any]
"""A record's values: JSON's types (a part's arrays as lists)."""

Origins = dict[str, tuple[int, int]]
"""The files the values were made from, with their (size, mtime_ns) when the part read them."""

_memo: dict[str, Facts] = {}
"""The records read in this process, by key (robosuite makes its parts again at every hard reset)."""


_shipped: dict[type, str] = {}
"""Spec classes made from a shipped spec file the registry held (read for robosuite), with that file:
the classes whose make records are kept (a variant made from the same file is another class)."""


def held_file(family: str, name: str) -> Path | None:
    """The file the registry holds ``name`` by (not read yet), if it holds it by one."""
    files = getattr(REGISTRIES[family].unmade, "files", None)
    found = files.get((family, name)) if isinstance(files, dict) else None
    return found if isinstance(found, Path) else None


def shipped_class(family: str, name: str, lookup: bool = True) -> Any:
    """The registry's class of a held name (its spec read now, or None from ``get`` when ``lookup``
    is False and there is none), noted as made from its shipped file."""
    file = held_file(family, name)
    spec_class = REGISTRIES[family].lookup(name) if lookup else REGISTRIES[family].get(name)
    if file is not None and spec_class is not None:
        _shipped[spec_class] = str(file)
    return spec_class


def spec_file(robosuite_class: type) -> str | None:
    """The shipped spec file of one of our robosuite classes when its make records are used (the
    cache on): its spec class not read yet (installed from its registration record), or made from
    that file for robosuite; None for any other class (a user's, an experiment's variant)."""
    if cache_disabled():
        return None
    found = inspect.getattr_static(robosuite_class, "assembler_class", None)
    if found is not None and not isinstance(found, type):  # a stand-in: the name the registry holds
        file = held_file(found.family, found.name)
        if file is not None:
            return str(file)
        found = REGISTRIES[found.family].get(found.name)
    return _shipped.get(found) if found is not None else None


def spec_class_of(robosuite_class: type) -> Any:
    """The spec class of one of our robosuite classes, looked up (its spec read) without putting it
    on the class: the class keeps answering from make records, and only the object that needs its
    part makes it."""
    found = inspect.getattr_static(robosuite_class, "assembler_class", None)
    if found is None or isinstance(found, type):
        return found
    return shipped_class(found.family, found.name)


def recorded_facts(material: Mapping[str, Any], make: Callable[[], tuple[Facts, Origins]]) -> Facts:
    """The values ``make()`` gives (with the files they were made from), from the record of
    ``material`` while those files are unchanged; else made now and recorded. ``make`` is called only
    on a miss (it makes the part: reads its spec and MJCF)."""
    key = buffer_digest(
        json.dumps(
            {
                "format": FORMAT,
                "kind": "robosuite-make",
                "assembler": code_fingerprint(),
                "mujoco": mujoco.__version__,
                "environment": resolution_environment(),
                **material,
            },
            sort_keys=True,
        ).encode()
    )
    if key in _memo:
        return _memo[key]
    made: list[tuple[Facts, Origins]] = []

    def read() -> Iterator[str]:  # iterated only on a miss: the part is made then
        made.append(make())
        yield from made[0][1]

    path = recorded_text_file(
        content_folder(PARTS),
        key,
        read(),
        lambda: json.dumps(made[0][0], sort_keys=True),
        ".json",
        lambda: made[0][1],
    )
    facts: Facts
    if made:  # made now: its own values, not their JSON (the record is for the next process)
        facts = json.loads(json.dumps(made[0][0]))
    else:
        try:
            facts = json.loads(path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            facts = json.loads(json.dumps(make()[0]))
    _memo[key] = facts
    return facts


def spec_origins(spec_class: type[models.PartModel]) -> tuple[Origin, ...]:
    """The spec files ``spec_class`` was made from (its parents' and motors' too), read only when a
    record is made: a warm make, answered from records, imports no spec reader."""
    from assembler.answers.request import part_origins

    return part_origins(spec_class)


def origins_of(parts: Iterable[models.PartModel]) -> Origins:
    """The files the values of ``parts`` were made from: each one's spec files (its parents' and
    its motors' too) and its MJCF with its includes, with their (size, mtime_ns) when read."""
    found: Origins = {}
    for part in parts:
        found.update({origin.path: (origin.size, origin.mtime_ns) for origin in spec_origins(type(part))})
        found.update({path: (size, mtime) for path, size, mtime in part.source.files})
    return found
