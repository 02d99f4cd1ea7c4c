"""Registration records: what robosuite's tables need of a shipped spec, kept in the cache, so that a
process whose specs did not change installs them without reading one.

Why: putting a name in robosuite's tables needs a handful of values (the family, whether the spec
enters robosuite, a robot's arms and robosuite Robot type, a base's type), but reading and
validating the spec that holds them costs about 2 ms a spec: 0.1 s at the bridge's import (19
shipped names robosuite does not have) and 0.09 s more at ``replace_robosuite()`` (the other 44),
most of what the bridge adds to a process. So the first process that reads a shipped spec for
robosuite records those values (:class:`Registration`) beside robosuite's part files, in the
cache's verified store (:func:`~assembler.cache.content.recorded_text_file`): keyed by the name,
its spec file, the assembler's code, MuJoCo's version and the resolution environment, and served
while every spec file it was made from (the spec, its parents, its motors' specs; a robot's base
too, which decides its Robot type) is unchanged. A process that finds the record installs a class
whose spec class (``assembler_class``) is looked up only when something uses it
(:class:`SpecClassOf`): the spec is read and validated then, with every check, and a spec error is
raised there as it is by any lookup. A miss, a changed file or the cache turned off reads the spec
as before, and records it. Names a user registered (already made) are never recorded: their
classes are at hand.
"""

from __future__ import annotations

import json
from collections.abc import Iterator
from dataclasses import asdict, dataclass
from typing import Any

import mujoco

from assembler import models
from assembler.cache.content import PARTS, content_folder, recorded_text_file
from assembler.cache.file_state import buffer_digest
from assembler.cache.key import code_fingerprint, resolution_environment
from assembler.errors import RegistryError
from assembler.files.cache_location import cache_disabled
from assembler.models.registering import REGISTRIES
from assembler.robosuite.conventions import base_in_robosuite, offered, robot_type_name
from assembler.robosuite.make_records import held_file, shipped_class, spec_origins
from assembler.robosuite.robot_class import check_offsets

FORMAT = 1
"""Version of a record's contents and key; bump it when either changes."""


@dataclass(frozen=True)
class Registration:
    """What robosuite's tables need of one spec class, as plain values."""

    family: str
    """robot, gripper or base (robosuite's table)."""

    name: str
    """The spec's name, the class name robosuite finds it by."""

    offered: bool
    """Whether the spec enters robosuite (:func:`~assembler.robosuite.conventions.offered`)."""

    arms: tuple[str, ...] = ()
    """A robot's arms, right first."""

    robot_type: str = ""
    """A robot's robosuite Robot class name (FixedBaseRobot, WheeledRobot, LeggedRobot)."""

    base_type: str = ""
    """A base's type (mount, mobile, legged, null): robosuite's model class for it."""

    def to_json(self) -> str:
        """The record's text."""
        return json.dumps({"format": FORMAT, **asdict(self)}, sort_keys=True)

    @classmethod
    def from_json(cls, text: str) -> Registration:
        """Parse a record; ValueError for anything that is not a whole record of this format."""
        try:
            data = json.loads(text)
            if data.pop("format") != FORMAT:
                raise ValueError("another format")
            return cls(
                family=str(data["family"]),
                name=str(data["name"]),
                offered=bool(data["offered"]),
                arms=tuple(str(arm) for arm in data["arms"]),
                robot_type=str(data["robot_type"]),
                base_type=str(data["base_type"]),
            )
        except (KeyError, TypeError, AttributeError) as error:
            raise ValueError(f"not a registration record: {error}") from None


def family_of(spec_class: type[models.PartModel]) -> str:
    """robot, gripper or base: robosuite's table for ``spec_class``."""
    if issubclass(spec_class, models.ManipulatorModel):
        return "robot"
    if issubclass(spec_class, models.GripperModel):
        return "gripper"
    if issubclass(spec_class, models.RobotBaseModel):
        return "base"
    raise RegistryError(f"{spec_class.__name__}: robosuite takes robots with arms, grippers and bases only")


def registration_of(spec_class: type[models.PartModel]) -> Registration:
    """The registration of a made spec class (its spec read); a robot whose ``base_xpos_offset``
    robosuite cannot read raises its spec error here, as making its robosuite class does."""
    family = family_of(spec_class)
    spec: Any = spec_class.spec
    if family == "robot":
        assert issubclass(spec_class, models.ManipulatorModel)
        check_offsets(spec_class)
        return Registration(
            family, spec_class.__name__, offered(spec_class), tuple(spec.arms), robot_type_name(spec_class)
        )
    if family == "base":
        return Registration(family, spec_class.__name__, True, base_type=str(spec.type))
    return Registration(family, spec_class.__name__, True)


class _Unrecorded(Exception):
    """No record for the held name: its file does not make it (the index misread the file), or its
    class is none robosuite takes."""


def _origins(spec_class: type[models.PartModel]) -> list[tuple[str, int, int]]:
    """The files the registration of ``spec_class`` depends on, with their (size, mtime_ns) when read."""
    classes = [spec_class]
    if issubclass(spec_class, models.ManipulatorModel):  # its base's type decides its Robot type
        base = REGISTRIES["base"].get(base_in_robosuite(spec_class.spec))
        classes += [base] if base is not None else []
    return [(origin.path, origin.size, origin.mtime_ns) for cls in classes for origin in spec_origins(cls)]


def recorded(family: str, name: str) -> Registration | None:
    """The registration of a held shipped name from its record, without reading its spec; None
    when there is no current record (the spec is read now, its class made and the record written:
    the caller installs the class) or the name is not held by a file (looked up as before)."""
    file = held_file(family, name)
    if file is None or cache_disabled():
        REGISTRIES[family].get(name)  # a lookup makes it (or says what is wrong with it)
        return None
    made: list[type[models.PartModel]] = []

    def read() -> Iterator[str]:  # iterated only on a miss: the spec is read then
        spec_class = shipped_class(family, name, lookup=False)
        if spec_class is None or not spec_origins(spec_class):
            raise _Unrecorded
        if issubclass(spec_class, models.ManipulatorModel):  # its base, read for its type, is recorded too
            recorded("base", base_in_robosuite(spec_class.spec))
        made.append(spec_class)
        yield from (path for path, _, _ in _origins(spec_class))

    material = {
        "format": FORMAT,
        "kind": "robosuite-registration",
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "environment": resolution_environment(),
        "family": family,
        "name": name,
        "file": str(file),
    }

    def emit() -> str:
        try:
            return registration_of(made[0]).to_json()
        except RegistryError:  # not a class robosuite takes (a robot without arms): none to record
            raise _Unrecorded from None

    key = buffer_digest(json.dumps(material, sort_keys=True).encode())
    try:
        path = recorded_text_file(
            content_folder(PARTS),
            key,
            read(),
            emit,
            ".json",
            lambda: {path: (size, mtime) for path, size, mtime in _origins(made[0])},
        )
    except _Unrecorded:  # its class, made now if it has one, is installed as before (if at all)
        return None
    if made:
        return None
    try:
        return Registration.from_json(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        REGISTRIES[family].get(name)
        return None


class SpecClassOf:
    """A robosuite class's ``assembler_class`` before it is read: the registry's class of the name,
    looked up (its spec read and validated) on first use, then kept on the class."""

    def __init__(self, family: str, name: str) -> None:
        self.family = family
        self.name = name
        self.owner: type | None = None

    def __set_name__(self, owner: type, attribute: str) -> None:
        self.owner = owner

    def __get__(self, instance: object, owner: type | None = None) -> type[models.PartModel]:
        spec_class: type[models.PartModel] = shipped_class(self.family, self.name)
        if self.owner is not None:
            setattr(self.owner, "assembler_class", spec_class)  # noqa: B010 (looked up once)
        return spec_class
