"""XML from strangers that is not MJCF (a URDF's outline, a ROS ``package.xml``, a COLLADA mesh):
one streaming pass, before any parser that builds or expands anything.

The same rule as for MJCF (:mod:`assembler.mjcf.xml_guard`): a document type declaration is where
XML entities are declared, whose expansion is unbounded ("billion laughs") or reads other local
files (external entities), and none of these formats needs one. :func:`stream` runs expat over the
text, building nothing, refuses a DTD, and lets the caller's handlers stop it with one line.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable
from typing import TYPE_CHECKING

from assembler.errors import MjcfError

if TYPE_CHECKING:
    import xml.etree.ElementTree as ET

EXPAT, ELEMENT_TREE = "xml.parsers.expat", "xml.etree.ElementTree"
"""Imported on the first document read (~5 ms with pyexpat): every cached answer imports this module
(through :mod:`assembler.files.paths` and :mod:`assembler.files.repositories`) and reads no XML."""

Start = Callable[[str, dict[str, str], int], None]
"""A handler of an element's start: its tag, its attributes and its line."""


class StopReading(Exception):
    """Raised by a handler to stop the pass; its message is the one line the reader gets."""


def stream(
    data: bytes,
    shown: str,
    start: Start | None = None,
    end: Callable[[str], None] | None = None,
    error: type[Exception] = MjcfError,
) -> None:
    """One expat pass over ``data`` (the file shown as ``shown``) calling ``start`` and ``end``;
    ``error`` with one line if it is not well-formed, declares a document type, or a handler stops it."""
    expat = importlib.import_module(EXPAT)
    parser = expat.ParserCreate()

    def doctype(*_: object) -> None:
        raise StopReading(
            f"{shown}: a document type declaration (<!DOCTYPE ...>) is not allowed: XML entities are "
            "declared there and their expansion is unbounded; remove it"
        )

    parser.StartDoctypeDeclHandler = doctype
    if start is not None:
        handler = start
        parser.StartElementHandler = lambda tag, attributes: handler(
            tag, attributes, parser.CurrentLineNumber
        )
    if end is not None:
        parser.EndElementHandler = end
    try:
        parser.Parse(data, True)
    except StopReading as stop:
        raise error(str(stop)) from None
    except (expat.ExpatError, LookupError) as problem:  # LookupError: an unknown encoding
        raise error(f"{shown}: not well-formed XML: {problem}") from None


def check_plain_xml(data: bytes, shown: str, error: type[Exception] = MjcfError) -> None:
    """Refuse ``data`` if it is not well-formed XML or declares a document type; reads nothing else."""
    stream(data, shown, error=error)


def parse_plain_xml(data: bytes, shown: str, error: type[Exception] = MjcfError) -> ET.Element:
    """The root element of ``data``, after :func:`check_plain_xml`."""
    check_plain_xml(data, shown, error)
    root: ET.Element = importlib.import_module(ELEMENT_TREE).fromstring(data)
    return root
