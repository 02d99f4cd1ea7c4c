"""Emitted MJCF: written precisely, bundled with its assets, and edited in place as text.

Emitted MJCF: text precise enough to reload the same model, and a self-contained bundle with
its assets (written by :mod:`assembler.files.bundles`, the one door for outputs).

Attribute values replaced in MJCF text that MuJoCo's writer emitted, leaving every other byte as it is.

A variant that a patch describes differs from its robot's emitted XML in a few attribute values
of named elements (a joint's damping, an actuator's gains, the home key). Re-emitting the whole
model for that (``MjSpec.to_xml``) costs tens of milliseconds for a Panda, compiling it first;
splicing the new values into the text costs a fraction of a millisecond. Elements are found by
their tag and ``name`` attribute as MuJoCo writes them (``<joint name="robot0_joint1" ...``);
an element that is not there exactly once is :class:`NotInText`, and the caller builds the
variant the full way. Numbers are written with ``repr``, which reads back to the same double.
"""

from __future__ import annotations

import contextlib
import ctypes
import functools
import re
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

import mujoco

from assembler.files.bundles import bundle_xml

XML_SIGNIFICANT_DIGITS = 15
"""Digits written per number: round-trips every value to 1e-15 yet keeps 0.1 as "0.1"."""

EXACT_DIGITS = 17
"""Digits that give every double back exactly (what robosuite must read to rebuild our model bit for bit)."""


@functools.lru_cache(maxsize=1)
def _mujoco_library() -> ctypes.CDLL | None:
    folder = Path(mujoco.__file__).parent
    for pattern in ("libmujoco.so*", "libmujoco*.dylib", "mujoco.dll"):
        for candidate in sorted(folder.glob(pattern)):
            with contextlib.suppress(OSError):
                return ctypes.CDLL(str(candidate))
    return None


@contextlib.contextmanager
def _xml_precision(digits: int) -> Iterator[None]:
    """Make MuJoCo's XML writer print ``digits`` significant digits instead of its default 6.

    With 6 digits, armature 5/3 is saved as 1.66667 and the reloaded model differs from the
    compiled one by 2e-6. MuJoCo exports the switch its own tests use (``FullFloatPrecision`` in
    src/xml/xml_numeric_format.h); when a MuJoCo build lacks it we fall back to the default.
    """
    library = _mujoco_library()
    setter = getattr(library, "_mjPRIVATE__set_xml_precision", None) if library else None
    getter = getattr(library, "_mjPRIVATE__get_xml_precision", None) if library else None
    if setter is None or getter is None:
        yield
        return
    getter.restype = ctypes.c_int
    previous = getter()
    setter(ctypes.c_int(digits))
    try:
        yield
    finally:
        setter(ctypes.c_int(previous))


def to_xml(spec: mujoco.MjSpec, digits: int = XML_SIGNIFICANT_DIGITS) -> str:
    """The spec as MJCF text, with numbers precise enough to reload the same model."""
    with _xml_precision(digits):
        return str(spec.to_xml())


def bundle(spec: mujoco.MjSpec, directory: Path, xml_name: str) -> Path:
    """Write ``directory/xml_name`` and copies of every asset file under ``directory/assets``
    (see :func:`bundle_xml`)."""
    return bundle_xml(to_xml(spec), directory, xml_name)


_TAG = re.compile(r"<(?P<tag>[A-Za-z_]+)\b(?P<attributes>[^<>]*?)(?P<end>/?)>")
_ATTRIBUTE = re.compile(r'\s(?P<name>[A-Za-z_:]+)="(?P<value>[^"]*)"')
_PLAIN_NAME = re.compile(r"^[A-Za-z0-9_.:\-/]+$")
"""Names MuJoCo's writer writes verbatim (nothing it would escape)."""


class NotInText(LookupError):
    """An element to edit is not in the text exactly once, or its name would be escaped."""


def numbers(values: Iterable[float]) -> str:
    """Values as MJCF writes a list of numbers, each exact (``repr``) and trailing zeros dropped
    (MuJoCo fills an attribute's missing values with zeros, as the writer relies on too)."""
    listed = [float(v) for v in values]
    while len(listed) > 1 and listed[-1] == 0.0:
        listed.pop()
    return " ".join(repr(v) for v in listed)


@dataclass
class _Tag:
    start: int
    end: int
    tag: str
    attributes: dict[str, str]
    closing: str


@dataclass
class XmlText:
    """The emitted XML of a robot, indexed once by (tag, name), and edits to splice into it."""

    text: str
    _index: dict[tuple[str, str], list[_Tag]] = field(default_factory=dict)

    def __post_init__(self) -> None:
        for match in _TAG.finditer(self.text):
            attributes = {m["name"]: m["value"] for m in _ATTRIBUTE.finditer(match["attributes"])}
            name = attributes.get("name")
            if name is not None:
                tag = _Tag(match.start(), match.end(), match["tag"], attributes, match["end"])
                self._index.setdefault((match["tag"], name), []).append(tag)

    def find(self, tag: str, name: str) -> tuple[str, str]:
        """The (tag, name) of an element present exactly once, checked (raises :class:`NotInText`)."""
        if not _PLAIN_NAME.match(name) or len(self._index.get((tag, name), ())) != 1:
            raise NotInText(f"<{tag} name='{name}'> is not in the emitted XML exactly once")
        return tag, name

    def attribute(self, tag: str, name: str, attribute: str) -> str | None:
        """The attribute's text on the element as written (None: not written, a default applies)."""
        return self._index[self.find(tag, name)][0].attributes.get(attribute)

    def edited(self, edits: dict[tuple[str, str], dict[str, str]]) -> str:
        """The text with each element's attributes replaced or added: ``{(tag, name): {attr: text}}``."""
        found = [(self._index[self.find(*element)][0], new) for element, new in edits.items() if new]
        changed = sorted(found, key=lambda pair: pair[0].start)
        pieces: list[str] = []
        at = 0
        for element, new in changed:
            attributes = {**element.attributes, **new}
            written = "".join(f' {key}="{value}"' for key, value in attributes.items())
            pieces += [self.text[at : element.start], f"<{element.tag}{written}{element.closing}>"]
            at = element.end
        pieces.append(self.text[at:])
        return "".join(pieces)
