"""XML from strangers that is not MJCF: a ROS ``package.xml``, a COLLADA mesh. Checked before any parser.

The same rule as for MJCF (:mod:`assembler.mjcf.xml_guard`): a document type declaration is where
XML entities are declared, whose expansion is unbounded ("billion laughs") or reads other local
files (external entities), and none of these formats needs one. A streaming expat pass that builds
nothing refuses it before ElementTree, pycollada or anything else parses the text.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
import xml.parsers.expat

from assembler.errors import MjcfError


class _Refused(Exception):
    """Raised inside an expat handler to stop the parse at once."""


def check_plain_xml(data: bytes, shown: str, error: type[Exception] = MjcfError) -> None:
    """Refuse ``data`` (the text of the file shown as ``shown``) if it is not well-formed XML or
    declares a document type; reads nothing else."""
    parser = xml.parsers.expat.ParserCreate()

    def doctype(*_: object) -> None:
        raise _Refused

    parser.StartDoctypeDeclHandler = doctype
    try:
        parser.Parse(data, True)
    except _Refused:
        raise error(
            f"{shown}: a document type declaration (<!DOCTYPE ...>) is not allowed: XML entities are "
            "declared there and their expansion is unbounded; remove it"
        ) from None
    except xml.parsers.expat.ExpatError as problem:
        raise error(f"{shown}: not well-formed XML: {problem}") from None


def parse_plain_xml(data: bytes, shown: str, error: type[Exception] = MjcfError) -> ET.Element:
    """The root element of ``data``, after :func:`check_plain_xml`."""
    check_plain_xml(data, shown, error)
    return ET.fromstring(data)
