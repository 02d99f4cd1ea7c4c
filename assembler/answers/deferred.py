"""``assembler.assemble`` and ``assembler.create_robot`` as users call them: a robot asked for before
is answered from the cache, and the schema, model classes and specs are read only when the robot is
used for something the cache cannot answer.

Why: ``import assembler; assembler.assemble("Panda").get_model()`` is the README's first line, and
importing the schema and model layers and validating the specs costs several times MuJoCo's load
of the cached model (a Panda: 0.55 s of CPU against 0.09 s). So when the same request was answered
before in this environment (a request record, :mod:`assembler.answers.records`: the same arguments,
every spec file it was made from unchanged), the robot starts as a :class:`DeferredRobot` that
holds only the request: ``get_model()``, ``get_xml()`` and ``save()`` are answered from the record's
cache entry. Anything else (any other attribute or method, ``isinstance``, ``repr``) first turns
the object into the real robot *in place*: its class becomes the robot's class and it is
initialised exactly as ``assemble`` makes it, so it is the same object from then on, with the
type, attributes and methods of the robot ``assemble`` returns. It is never a wrapper: code that
holds it keeps holding the robot.

A request without a record (the first time, a changed spec) takes the full path at once, so every
error is raised by ``assemble`` as always, and is recorded, so that the next process is answered
from the cache. A process that has the model classes imported already (it made a robot, or
imported them) makes every robot at once: that is cheap then, and the object is a plain robot.
"""

from __future__ import annotations

import importlib
import os
import sys
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco

from assembler.answers.load_model import assembly_request
from assembler.answers.records import KeyedRequest, record_of, recorded_model, recorded_xml
from assembler.cache.requests import RequestRecord
from assembler.compiler.keyframe import Keyframe
from assembler.compiler.stored import entry_key
from assembler.files.cache_location import volatile_folders
from assembler.files.writing import write_atomically
from assembler.spec.part_arguments import DEFAULT, ArgumentKind, argument_kind

ASSEMBLE = "load_model"
"""The request kind of ``assemble``: ``load_model``'s, whose answer is ``assemble(...).get_model()``."""
CREATE_ROBOT = "create_robot"

MODEL_CLASSES = "assembler.models"
"""Once the model classes are imported, a robot is made at once: making one then costs about a
millisecond, so deferring it would save nothing and only make ``type(robot)`` a surprise."""

_PENDING = "_deferred_request"
"""The one attribute a deferred robot holds (a name no robot attribute uses)."""

_SET_CLASS = object.__dict__["__class__"].__set__
"""Python's own ``obj.__class__ = cls`` (a deferred robot's ``__class__`` is its property below)."""


@dataclass(frozen=True)
class RobotArguments:
    """What ``assemble`` or ``create_robot`` was called with."""

    kind: str
    """``assemble`` (with base and grippers) or ``create_robot`` (the robot alone)."""

    robot: str
    idn: int | str
    base: str | None
    grippers: Mapping[str, str | None] | None
    overrides: Any


@dataclass
class _Pending:
    """A deferred robot's state: its request, the record that answers it, the arguments to make
    it with, the last model it handed out (its keyframe goes to the real robot), and its class once
    asked for."""

    request: KeyedRequest
    record: RequestRecord
    arguments: RobotArguments
    model: mujoco.MjModel | None = None
    cls: type | None = None


def _robot_class(pending: _Pending) -> type:
    """The class the deferred robot will be (one class: with overrides, each lookup makes a new one)."""
    if pending.cls is None:
        pending.cls = _full_path().robot_class(pending.arguments.robot, pending.arguments.overrides)
    return pending.cls


def _full_path() -> Any:
    # The schema, model classes and registry: imported only when a robot is really made, which is
    # what keeps a cached answer free of them (tests/answers/test_deferred.py checks sys.modules).
    return importlib.import_module("assembler.registry.instances")


def _made_now(arguments: RobotArguments) -> Any:
    """The robot ``arguments`` describe, made by the registry (errors raised as ``assemble`` raises them)."""
    instances = _full_path()
    if arguments.kind == CREATE_ROBOT:
        return instances.create_robot(arguments.robot, idn=arguments.idn, overrides=arguments.overrides)
    return instances.assemble(
        arguments.robot, arguments.idn, arguments.base, arguments.grippers, arguments.overrides
    )


def _materialise(robot: DeferredRobot) -> Any:
    """Turn ``robot`` into the real robot, in place (see the module's docstring); returns it."""
    pending: _Pending = robot.__dict__[_PENDING]
    arguments = pending.arguments
    instances = _full_path()
    cls: Any = _robot_class(pending)
    robot.__dict__.clear()
    _SET_CLASS(robot, cls)
    try:
        cls.__init__(robot, idn=arguments.idn)  # as cls(idn=...) does, on this object
        if arguments.kind == ASSEMBLE:
            instances.equip(robot, arguments.base, arguments.grippers)
    except BaseException:  # a spec file changed since the record was read: stay as it was, raise
        robot.__dict__.clear()
        _SET_CLASS(robot, DeferredRobot)
        robot.__dict__[_PENDING] = pending
        raise
    if pending.model is not None:  # as RobotModel.get_model leaves it: its mjspec gets this keyframe
        robot._keyframe = Keyframe.of(pending.model)
        robot.entry_key = pending.record.model_key
    return robot


class DeferredRobot:
    """A robot from ``assemble``/``create_robot`` that is still its request (see the module)."""

    def __init__(self, pending: _Pending) -> None:
        self.__dict__[_PENDING] = pending

    def get_model(self, cache: bool = True, store: bool = True) -> mujoco.MjModel:
        """As :meth:`RobotModel.get_model`: from the record's cache entry while it is there."""
        pending: _Pending = self.__dict__[_PENDING]
        if cache:
            model = recorded_model(pending.record)
            if model is not None:
                pending.model = model
                return model
        return _materialise(self).get_model(cache, store)

    def get_xml(self, cache: bool = True, store: bool = True, meshes: bool = True) -> str:
        """As :meth:`RobotModel.get_xml`: from the record's cache entry when it holds the XML."""
        pending: _Pending = self.__dict__[_PENDING]
        if cache:
            xml = recorded_xml(pending.record)
            if xml is not None:
                return xml
        return _materialise(self).get_xml(cache, store, meshes)  # type: ignore[no-any-return]

    def save(self, path: str | Path, cache: bool = True) -> Path:
        """As :meth:`RobotModel.save`: the MJCF written to ``path``, with the assets it names in the
        cache folder copied beside it (the copying module is loaded only for a model that names one)."""
        xml, target = self.get_xml(cache=cache), Path(path)
        if not any(os.fspath(folder) in xml for folder in volatile_folders()):
            write_atomically(target, xml)
            return target
        return importlib.import_module("assembler.files.bundles").save_model(xml, target)  # type: ignore[no-any-return]

    # Anything else is the real robot's: made on first use, in place.

    def __getattr__(self, name: str) -> Any:
        if _PENDING not in self.__dict__:  # being rebuilt by copy or pickle: its state comes next
            raise AttributeError(name)
        return getattr(_materialise(self), name)

    def __setattr__(self, name: str, value: Any) -> None:
        setattr(_materialise(self), name, value)

    def __delattr__(self, name: str) -> None:
        delattr(_materialise(self), name)

    def __repr__(self) -> str:
        return repr(_materialise(self))

    def __dir__(self) -> list[str]:
        return dir(_materialise(self))

    @property  # type: ignore[misc]
    def __class__(self) -> type:  # noqa: F811
        # isinstance(robot, RobotModel) asks this when type(robot) is not one: the robot's class,
        # without making the robot (Python compares it with type(robot), read after this returns).
        return _robot_class(self.__dict__[_PENDING])


def _answered_or_made(arguments: RobotArguments) -> Any:
    """A deferred robot when the request has a record and the model classes are not imported yet;
    else the robot made now (and its request recorded when it had no record)."""
    if argument_kind(arguments.robot) is not ArgumentKind.NAME:
        return _made_now(arguments)  # a spec file is not a registered name: the registry says so
    given = arguments
    request = assembly_request(
        given.robot, given.idn, given.base, given.grippers, given.overrides, (), given.kind
    )
    record = record_of(request)
    if record is not None and MODEL_CLASSES not in sys.modules:
        return DeferredRobot(_Pending(request, record, arguments))
    robot = _made_now(arguments)
    if record is not None:
        return robot
    # Recorded now, under the key its inputs hash to (get_model stores the entry there): nothing
    # here reads MJCF or compiles. The record's own rules decide whether it can be kept.
    robot.entry_key = entry_key(robot.build_inputs())
    importlib.import_module("assembler.answers.request").record_answer(request, robot, [], None)
    return robot


def assemble(
    robot: str,
    idn: int | str = 0,
    base: str | None = DEFAULT,
    grippers: Mapping[str, str | None] | None = None,
    overrides: Any = None,
) -> Any:
    """:func:`assembler.registry.instances.assemble`, answered from the cache when it can be."""
    return _answered_or_made(RobotArguments(ASSEMBLE, robot, idn, base, grippers, overrides))


def create_robot(robot_name: str, *args: object, overrides: Any = None, **kwargs: object) -> Any:
    """:func:`assembler.registry.instances.create_robot`, answered from the cache when it can be
    (a robot made with arguments other than ``idn`` is made now)."""
    if len(args) + len(kwargs) > 1 or set(kwargs) - {"idn"}:
        return _full_path().create_robot(robot_name, *args, overrides=overrides, **kwargs)
    idn = args[0] if args else kwargs.get("idn", 0)
    if not isinstance(idn, (int, str)):
        return _full_path().create_robot(robot_name, *args, overrides=overrides, **kwargs)
    return _answered_or_made(RobotArguments(CREATE_ROBOT, robot_name, idn, None, None, overrides))
