"""Answering a repeated request from its record, and recording a request the slow path answered.

:func:`answered_model` and :func:`answered_xml` need nothing but this cache layer and MuJoCo: no
schema, no spec, no MJCF is read. A request is plain JSON data (what the caller was given, as
given); its record (:mod:`assembler.cache.requests`) names the model entry, whose own files are
checked as on every load. :func:`record` is called by the slow path once it has answered.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import mujoco

from assembler.cache.dependencies import Recorder
from assembler.cache.requests import RequestRecord, default_request_store, folder_stats, request_key
from assembler.compiler.stored import default_store, load_entry
from assembler.files.cache_location import cache_disabled
from assembler.patch.derived import kept_model

Request = Mapping[str, Any]
"""A request as plain JSON data: what was asked for, exactly as given."""


@dataclass(frozen=True)
class Origin:
    """A spec file an answer was made from, as it was when it was read."""

    path: str
    size: int
    mtime_ns: int


@dataclass(frozen=True)
class KeyedRequest:
    """A request with its key in this environment, hashed once for both its lookup and its record."""

    data: Request
    key: str | None
    """None when the request holds something that is not plain data: never answered nor recorded."""


def keyed(request: Request) -> KeyedRequest:
    """``request`` with its key."""
    return KeyedRequest(request, request_key(request))


def record_of(request: KeyedRequest) -> RequestRecord | None:
    """The record of a request answered before, if nothing it was made from changed (None with the
    cache disabled, or for a request that is not plain data)."""
    if cache_disabled() or request.key is None:
        return None
    return default_request_store().load(request.key)


_record_of = record_of  # the name tests/cache/test_request_records.py imports


def answered_model(request: KeyedRequest) -> mujoco.MjModel | None:
    """The compiled model of a request answered before, if nothing it was made from changed."""
    record = record_of(request)
    return None if record is None else recorded_model(record)


def recorded_model(record: RequestRecord) -> mujoco.MjModel | None:
    """The model a record names, if its entry is still there with its files unchanged: stored, or
    (a patched variant) made from the plain robot's entry by the patch kept in its place."""
    model = load_entry(record.model_key)
    return model if model is not None else kept_model(record.model_key)


def recorded_xml(record: RequestRecord) -> str | None:
    """The XML a record's entry holds, if it holds its XML and its files are unchanged."""
    return default_store().load_xml(record.model_key)


def answered_xml(request: KeyedRequest) -> tuple[str, RequestRecord] | None:
    """The emitted XML of a request answered before, and its record (the notes printed with it
    then), if nothing it was made from changed and the entry holds its XML."""
    record = record_of(request)
    if record is None:
        return None
    xml = recorded_xml(record)
    return None if xml is None else (xml, record)


def record(
    request: KeyedRequest,
    model_key: str,
    origins: Iterable[Origin],
    roots: Iterable[Path],
    notes: Iterable[str] = (),
    name: str = "",
) -> bool:
    """Record that ``request`` is answered by the entry ``model_key``, made from the spec files
    ``origins`` (a file changed since it was read means no record), with the registry read from the
    folders below ``roots``; returns whether a record was written."""
    key = request.key
    if key is None or cache_disabled():
        return False
    read = {origin.path: (origin.size, origin.mtime_ns) for origin in origins}
    specs = Recorder(read, read).result()
    if specs is None:
        return False
    found = RequestRecord(model_key, tuple(specs), folder_stats(roots), tuple(notes), name)
    default_request_store().save(key, found)
    return True
