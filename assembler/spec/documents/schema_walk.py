"""Walking a pydantic schema along a field path: which keys exist at a level, what type a field has.

One walker serves every place that needs to know the schema's shape: "unknown key ... Valid keys
here" in validation messages, and ``--set``/``overrides:`` paths, which must exist before a value
is put there. Each step either returns the annotation one level down or raises
:class:`SchemaMiss` saying, in the user's terms, why the schema has no such place.
"""

from __future__ import annotations

import types
import typing
from collections.abc import Collection
from typing import Any

from pydantic import BaseModel

from assembler.errors import did_you_mean
from assembler.spec.fieldpath import FieldPath

UNKNOWN: Any = object()
"""The data at a place is not known (only the schema is walked)."""


class SchemaMiss(Exception):
    """A path the schema does not allow; the message says why and what exists instead."""


def branches(annotation: Any) -> list[Any]:
    """The alternatives of ``X | Y`` and ``Optional[X]``, without ``Annotated``'s metadata."""
    if typing.get_origin(annotation) is typing.Annotated:
        return branches(typing.get_args(annotation)[0])
    if typing.get_origin(annotation) is typing.Union or isinstance(annotation, types.UnionType):
        return [b for arg in typing.get_args(annotation) for b in branches(arg)]
    return [annotation]


def is_model(annotation: Any) -> bool:
    """True for a pydantic model class."""
    return isinstance(annotation, type) and issubclass(annotation, BaseModel)


def unknown_key_message(key: str, valid: Collection[str]) -> str:
    """The one wording of an unknown key, with the closest valid key and all of them."""
    ordered = sorted(valid)
    return f"unknown key '{key}'.{did_you_mean(key, ordered)} Valid keys here: {', '.join(ordered)}"


def step(
    annotation: Any,
    part: str | int,
    here: FieldPath,
    container: Any = UNKNOWN,
    hidden: Collection[str] = (),
) -> Any:
    """The annotation of ``part`` below ``here`` (whose annotation is ``annotation`` and whose data,
    when known, is ``container``); raises :class:`SchemaMiss`. ``hidden`` keys are not offered."""
    options = branches(annotation)
    sequences = [b for b in options if typing.get_origin(b) in (list, tuple)]
    if isinstance(part, str):
        models = [b for b in options if is_model(b)]
        for model in models:
            if part in model.model_fields and part not in hidden:
                return model.model_fields[part].annotation
        for option in options:
            if typing.get_origin(option) is dict:
                return typing.get_args(option)[1]
        if models:
            valid = {name for model in models for name in model.model_fields} - set(hidden)
            raise SchemaMiss(unknown_key_message(part, valid))
        if sequences:
            raise SchemaMiss(f"{here} is a list; pick an item by index, e.g. {here}[0]")
        raise SchemaMiss(f"{here} holds a single value, not keys; set it whole: {here}=VALUE")
    if not sequences:
        raise SchemaMiss(f"{here} is not a list; drop the index [{part}]")
    if container is not UNKNOWN:
        if not isinstance(container, list):
            shown = "not set" if container in (None, {}) else f"{container!r}, not a list"
            raise SchemaMiss(f"{here} is {shown}; set the whole list: {here}=[...]")
        if part >= len(container):
            raise SchemaMiss(
                f"index {part} is out of range: {here} has {len(container)} values "
                f"(indexes 0 to {len(container) - 1})"
            )
    arguments = typing.get_args(sequences[0])
    return arguments[0] if arguments else Any


def keys_at(model: type[BaseModel], path: FieldPath) -> list[str]:
    """The keys a document may use at ``path`` (following nested models, lists and mappings)."""
    annotation: Any = model
    for depth, part in enumerate(path):
        try:
            annotation = step(annotation, part, FieldPath(path[:depth]))
        except SchemaMiss:
            return []
    return sorted(
        {name for option in branches(annotation) if is_model(option) for name in option.model_fields}
    )
