"""Dotted overrides (``joint_defaults.damping=0.2``, ``init_qpos[3]=-2.0``) applied to a spec.

An override edits the spec's merged YAML mapping (``extends`` already resolved) before it is
validated, so its value is typed and checked by the same schema as a value written in the file,
and ``spec`` of the result says what was built (a model cache keyed on the spec sees it). The
path is checked against the schema first, so a typo lists the keys that exist at that level.

The overridden part is a new subclass with the original's name that is *not* registered: the
registry keeps the reviewed spec, and two experiments overriding one robot never collide.
"""

from __future__ import annotations

import copy
import re
import types
import typing
from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING, Any, TypeVar

import yaml
from pydantic import BaseModel, ValidationError

from assembler.errors import AssemblerError, Location, Problem, SpecError, did_you_mean
from assembler.loader import PATH_FIELDS, LoadedSpec, problems_from_validation
from assembler.paths import resolve_model_path
from assembler.yaml_source import DataPath, LocatedDocument, dotted

if TYPE_CHECKING:
    from assembler.models import PartModel

FIXED_FIELDS: tuple[str, ...] = ("name", "extends", "kind", "morphology")
"""Fields that choose the class itself; changing them is a new spec (``extends:``), not an override."""

_SEGMENT = re.compile(r"(?P<key>[^.\[\]\s=]+)(?P<indexes>(?:\[-?\d+\])*)$")


@dataclass(frozen=True)
class Override:
    """One value for one field path, and how an error about it names it."""

    path: DataPath
    value: Any
    label: str = "override "
    """Written before the path in errors: ``--set ``, ``robots[0].overrides.``."""

    location: Location | None = None
    """Where the override was written (an experiment file), if anywhere."""

    @property
    def key(self) -> str:
        """The path as users write it: ``init_qpos[3]``."""
        return dotted(self.path)

    def problem(self, message: str, path: DataPath | None = None) -> Problem:
        """A problem about this override (or a field below it), named as the user wrote it."""
        return Problem(message, self.location, self.label + dotted(self.path if path is None else path))


Overrides = Mapping[str, Any] | Iterable[str | Override] | None
"""``{"joint_defaults.damping": 0.2}``, ``["init_qpos[3]=-2.0"]``, parsed overrides, or None."""


def parse_path(text: str, label: str = "override ", location: Location | None = None) -> DataPath:
    """``init_qpos[3]`` -> ``("init_qpos", 3)``; a malformed path is a :class:`SpecError`."""
    path: list[str | int] = []
    for segment in text.split("."):
        match = _SEGMENT.match(segment)
        if match is None:
            raise SpecError(
                Problem(
                    "expected a dotted path such as joint_defaults.damping or init_qpos[3]",
                    location,
                    label + text,
                )
            )
        path.append(match["key"])
        for index in re.findall(r"\[(-?\d+)\]", match["indexes"]):
            if int(index) < 0:
                raise SpecError(Problem(f"index {index}: count from 0", location, label + text))
            path.append(int(index))
    return tuple(path)


def parse_override(text: str, label: str = "override ") -> Override:
    """``PATH=VALUE``, the value read as YAML (``0.2``, ``[0.1, 0.2]``, ``null``, ``{inverse_index: 3}``)."""
    key, sep, raw = text.partition("=")
    if not sep or not key.strip():
        raise SpecError(
            Problem(
                f"expected PATH=VALUE (e.g. joint_defaults.damping=0.2), got '{text}'", None, label.strip()
            )
        )
    path = parse_path(key.strip(), label)
    try:
        value = yaml.safe_load(raw)
    except yaml.YAMLError as error:
        reason = getattr(error, "problem", None) or "invalid YAML"
        raise SpecError(
            Problem(f"the value '{raw}' is not valid YAML ({reason})", None, label + key)
        ) from None
    return Override(path, value, label)


def parse_overrides(overrides: Overrides, label: str = "override ") -> list[Override]:
    """Every accepted form of overrides as a list of :class:`Override`, in order."""
    if overrides is None:
        return []
    if isinstance(overrides, Mapping):
        return [Override(parse_path(str(key), label), value, label) for key, value in overrides.items()]
    if isinstance(overrides, str):
        overrides = [overrides]
    return [item if isinstance(item, Override) else parse_override(item, label) for item in overrides]


# ----- walking the schema -------------------------------------------------------------------


class _Miss(Exception):
    """An override path that the schema does not allow (internal: becomes a Problem)."""


def _branches(annotation: Any) -> list[Any]:
    """The alternatives of ``X | Y`` and ``Optional[X]``, without Annotated's metadata."""
    if typing.get_origin(annotation) is typing.Annotated:
        return _branches(typing.get_args(annotation)[0])
    if typing.get_origin(annotation) is typing.Union or isinstance(annotation, types.UnionType):
        return [b for arg in typing.get_args(annotation) for b in _branches(arg)]
    return [annotation]


def _is_model(annotation: Any) -> bool:
    return isinstance(annotation, type) and issubclass(annotation, BaseModel)


def _child(annotation: Any, part: str | int, here: DataPath, container: Any) -> Any:
    """The annotation of ``part`` inside ``container`` (the value at ``here``, of type
    ``annotation``); raises ``_Miss`` saying why the schema has no such place."""
    branches = _branches(annotation)
    sequences = [b for b in branches if typing.get_origin(b) in (list, tuple)]
    if isinstance(part, str):
        if not here and part in FIXED_FIELDS:
            raise _Miss(f"'{part}' chooses the class and cannot be overridden; write a spec with extends:")
        models = [b for b in branches if _is_model(b)]
        for model in models:
            if part in model.model_fields:
                return model.model_fields[part].annotation
        for branch in branches:
            if typing.get_origin(branch) is dict:
                return typing.get_args(branch)[1]
        if models:
            valid = sorted({f for m in models for f in m.model_fields} - set(() if here else FIXED_FIELDS))
            raise _Miss(
                f"unknown key '{part}'.{did_you_mean(part, valid)} Valid keys here: {', '.join(valid)}"
            )
        if sequences:
            raise _Miss(f"{dotted(here)} is a list; pick an item by index, e.g. {dotted(here)}[0]")
        raise _Miss(f"{dotted(here)} holds a single value, not keys; set it whole: {dotted(here)}=VALUE")
    if not sequences:
        raise _Miss(f"{dotted(here)} is not a list; drop the index [{part}]")
    if not isinstance(container, list):
        shown = "not set" if container in (None, {}) else f"{container!r}, not a list"
        raise _Miss(f"{dotted(here)} is {shown}; set the whole list: {dotted(here)}=[...]")
    if part >= len(container):
        raise _Miss(
            f"index {part} is out of range: {dotted(here)} has {len(container)} values "
            f"(indexes 0 to {len(container) - 1})"
        )
    return typing.get_args(sequences[0])[0]


def _assign(data: dict[str, Any], model: type[BaseModel], override: Override) -> None:
    """Put ``override.value`` at its path in ``data``, creating mappings the file left out."""
    annotation: Any = model
    container: Any = data
    path = override.path
    for depth, part in enumerate(path):
        annotation = _child(annotation, part, path[:depth], container)
        if depth == len(path) - 1:
            value = override.value
            if depth == 0 and part in PATH_FIELDS and isinstance(value, str) and value:
                value = resolve_model_path(value, None)  # relative to the working directory
            container[part] = copy.deepcopy(value)
            return
        current = container.get(part) if isinstance(part, str) else container[part]
        if isinstance(path[depth + 1], str) and not isinstance(current, dict):
            # a mapping the file leaves out, or a rule given as a number now given as a mapping
            current = {}
            container[part] = current
        container = current


def apply_overrides(
    document: LocatedDocument, model: type[BaseModel], overrides: Sequence[Override]
) -> LocatedDocument:
    """A copy of ``document`` with the overrides applied; every bad path is reported at once."""
    data = copy.deepcopy(document.data)
    marks = dict(document.marks)
    problems: list[Problem] = []
    for override in overrides:
        try:
            _assign(data, model, override)
        except _Miss as miss:
            problems.append(override.problem(str(miss)))
            continue
        except SpecError as error:  # e.g. an mjcf path outside the allowed folders
            problems += [override.problem(p.message) for p in error.problems]
            continue
        # The file's positions no longer describe these values; errors name the override instead.
        for path in [p for p in marks if p[: len(override.path)] == override.path]:
            del marks[path]
    if problems:
        raise SpecError(problems)
    return LocatedDocument(data=data, file=document.file, marks=marks)


def _normal(path: str) -> str:
    """``joints.0.match`` and ``joints[0].match`` (both spellings occur in messages) as one."""
    return re.sub(r"\[(\d+)\]", r".\1", path)


def _blame(problem: Problem, overrides: Sequence[Override], note: bool = True) -> Problem:
    """Name the override a problem comes from; others keep the spec's position (and, with ``note``,
    say that overrides were applied, since one may have caused it indirectly)."""
    shown = _normal(problem.path or "")
    for override in reversed(overrides):  # the last override of a path is the one that counts
        key = _normal(override.key)
        if shown == key or shown.startswith(key + "."):
            return Problem(problem.message, override.location, override.label + (problem.path or key))
    if not note:
        return problem
    keys = ", ".join(o.key for o in overrides)
    return Problem(f"{problem.message} (with the overrides {keys})", problem.location, problem.path)


def overridden_spec(loaded: LoadedSpec, overrides: Sequence[Override]) -> LoadedSpec:
    """The spec ``loaded`` describes with ``overrides`` applied and validated."""
    model = type(loaded.spec)
    document = apply_overrides(loaded.document, model, overrides)
    data = {k: v for k, v in document.data.items() if k != "__dir__"}
    try:
        spec = model.model_validate(data)
    except ValidationError as error:
        problems = problems_from_validation(error, document, model)
        raise SpecError([_blame(p, overrides) for p in problems]) from None
    return LoadedSpec(spec=spec, document=document)


def _loaded_of(cls: type[PartModel]) -> LoadedSpec:
    if cls.loaded is not None:
        return cls.loaded
    # A class written in Python: its spec, as the mapping a file would hold.
    data = cls.spec.model_dump(mode="json")
    return LoadedSpec(spec=cls.spec, document=LocatedDocument(data, f"<class {cls.__qualname__}>"))


def check_paths(cls: type[PartModel], overrides: Sequence[Override]) -> None:
    """Raise :class:`SpecError` if a path does not exist in ``cls``'s spec; values are not checked."""
    loaded = _loaded_of(cls)
    apply_overrides(loaded.document, type(loaded.spec), overrides)


P = TypeVar("P", bound="PartModel")


def with_overrides(cls: type[P], overrides: Overrides, label: str = "override ") -> type[P]:
    """``cls`` itself when there is nothing to override, else an unregistered subclass of the
    same name whose ``spec`` has the overrides applied."""
    items = parse_overrides(overrides, label)
    if not items:
        return cls
    loaded = overridden_spec(_loaded_of(cls), items)

    def __init__(self: P, *args: Any, **kwargs: Any) -> None:
        # Checks against the MJCF (joint counts, names, files) name the override, not the spec.
        try:
            cls.__init__(self, *args, **kwargs)
        except AssemblerError as error:
            raise type(error)([_blame(p, items, note=False) for p in error.problems]) from None

    namespace = {
        "__init__": __init__,
        "abstract": True,  # the registry's metaclass skips it: the reviewed spec stays registered
        "spec": loaded.spec,
        "loaded": loaded,
        "applied_overrides": (*applied_overrides(cls), *items),
        "__doc__": cls.__doc__,
        "__module__": cls.__module__,
        "__qualname__": cls.__qualname__,
    }
    return type(cls.__name__, (cls,), namespace)


def applied_overrides(cls: type) -> tuple[Override, ...]:
    """The overrides a class was made with (none for a registered class)."""
    return tuple(getattr(cls, "applied_overrides", ()))
