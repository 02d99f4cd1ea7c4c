"""Emitted MJCF: text precise enough to reload the same model, and a self-contained bundle with
its assets (written by :mod:`assembler.files.bundles`, the one door for outputs).
"""

from __future__ import annotations

import contextlib
import ctypes
import functools
from collections.abc import Iterator
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
