"""Emitted MJCF: text precise enough to reload the same model, and a self-contained bundle with
its assets (written atomically, :mod:`assembler.files.writing`). A bundle writes only inside its folder:
asset names from the MJCF are reduced to plain names.
"""

from __future__ import annotations

import contextlib
import ctypes
import functools
import hashlib
import re
import xml.etree.ElementTree as ET
from collections.abc import Iterator
from pathlib import Path

import mujoco

from assembler.errors import AssemblerError
from assembler.files.paths import display_path
from assembler.files.writing import copy_atomically, make_folder, undone_on_failure, write_atomically

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


def _digest(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


FILE_ATTRIBUTES: tuple[str, ...] = (
    "file",
    "fileright",
    "fileleft",
    "fileup",
    "filedown",
    "filefront",
    "fileback",
)
"""Attributes of MJCF asset elements that name a file (cube textures have six)."""


_UNSAFE_CHARACTERS = re.compile(r"[^A-Za-z0-9._-]")


def _safe_name(name: str) -> str:
    """``name`` as a plain file name in the bundle: letters, digits and ``. _ -``, not hidden.

    Asset names come from a stranger's MJCF; whatever they hold, the copy stays in ``assets/``.
    """
    return _UNSAFE_CHARACTERS.sub("_", name).lstrip(".") or "asset"


def bundle(spec: mujoco.MjSpec, directory: Path, xml_name: str) -> Path:
    """Write ``directory/xml_name`` and copies of every asset file under ``directory/assets``
    (see :func:`bundle_xml`)."""
    return bundle_xml(to_xml(spec), directory, xml_name)


def bundle_xml(xml: str, directory: Path, xml_name: str) -> Path:
    """Write the emitted MJCF ``xml`` as ``directory/xml_name`` and copies of every asset file it
    names under ``directory/assets``.

    Asset paths in the XML become relative, so the folder can be moved or zipped. Two different
    files with one base name get distinct names (``link.stl``, ``link_1.stl``). The paths are
    rewritten in the emitted text: MjSpec would try to open relative paths from the source folder.
    """
    if Path(xml_name).name != xml_name or xml_name in ("", ".", ".."):
        raise AssemblerError(f"bundle: expected a file name for the XML, got '{xml_name}'")
    root = ET.fromstring(xml)
    assets = directory / "assets"
    with undone_on_failure(assets) as created:
        make_folder(assets)
        if not assets.resolve().is_relative_to(directory.resolve()):  # a link planted in the folder
            raise AssemblerError(f"{display_path(assets)} leads out of {display_path(directory)}; remove it")
        return _write_bundle(root, directory, assets, xml_name, created)


def _write_bundle(
    root: ET.Element, directory: Path, assets: Path, xml_name: str, created: list[Path]
) -> Path:
    placed: dict[str, str] = {}  # absolute source -> relative target
    taken: dict[str, str] = {}  # target name -> content digest

    def place(file: str) -> str:
        if file in placed:
            return placed[file]
        source = Path(file)
        digest = _digest(source)
        name = _safe_name(source.name)
        stem, suffix, n = Path(name).stem, Path(name).suffix, 0
        while name in taken and taken[name] != digest:
            n += 1
            name = f"{stem}_{n}{suffix}"
        if name not in taken:
            if not (assets / name).exists():
                created.append(assets / name)
            copy_atomically(source, assets / name)
            taken[name] = digest
        placed[file] = f"assets/{name}"
        return placed[file]

    for section in root.iter("asset"):
        for element in section:
            for attribute in FILE_ATTRIBUTES:
                if element.get(attribute):
                    element.set(attribute, place(element.get(attribute, "")))
    target = directory / xml_name
    if not target.exists():
        created.append(target)
    write_atomically(target, ET.tostring(root, encoding="unicode") + "\n")
    return target
