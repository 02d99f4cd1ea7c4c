"""Reading the vendor's file for ``assembler new``: the same readers a spec uses (:func:`load_mjcf`,
:func:`load_urdf`), the file named the way the spec will name it, and MuJoCo's compile of it, which
says whether a URDF's inertias need ``balance_inertia``.
"""

from __future__ import annotations

import os
import sys
import warnings
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import mujoco

from assembler.errors import MjcfError, Problem
from assembler.files import menagerie
from assembler.files.menagerie import MENAGERIE_SCHEME
from assembler.files.paths import PACKAGE_SCHEME, allowing, display_path, is_file, package_root
from assembler.files.regular import not_regular
from assembler.mjcf.source import MjcfSource, load_mjcf
from assembler.mjcf.xml_guard import NOT_FINITE
from assembler.spec.schema.fixes import MjcfFix
from assembler.urdf import load_urdf
from assembler.urdf.packages import share_reference
from assembler.urdf.postprocess import MUJOCO_IGNORES

Format = Literal["mjcf", "urdf"]

UNBALANCED_INERTIA = "A + B >= C"
"""The words of MuJoCo's refusal of an inertia that violates the triangle inequality."""


@dataclass(frozen=True)
class ModelFile:
    """The vendor's file as the spec names it, read and compiled."""

    path: Path
    format: Format
    reference: str
    """``package://NAME/...`` when the file lies in an installed Python package or (a URDF) in a ROS
    package of a ``share/`` tree the spec's ``package://`` resolves to, ``menagerie://...`` in a
    MuJoCo Menagerie model folder, else its absolute path (:func:`spec_reference` makes it relative to
    the spec)."""
    source: MjcfSource
    model: mujoco.MjModel
    balance_inertia: bool
    """True when MuJoCo refused the URDF's inertias until they were balanced."""


def file_format(path: Path) -> Format:
    """'urdf' for a ``.urdf`` file, else 'mjcf'."""
    return "urdf" if path.suffix.lower() == ".urdf" else "mjcf"


def python_package_reference(path: Path) -> str | None:
    """``package://NAME/inner/path`` when ``path`` lies in an installed top-level package NAME (found
    on ``sys.path``, as a spec's ``package://`` reference is), else None."""
    roots = {Path(entry).resolve() for entry in sys.path if entry and os.path.isdir(entry)}
    for folder in path.parents:
        if folder.parent in roots and folder.name.isidentifier():
            found = package_root(folder.name)
            if found is not None and found.resolve() == folder:
                return f"{PACKAGE_SCHEME}{folder.name}/{path.relative_to(folder).as_posix()}"
    return None


def spec_reference(model: ModelFile, spec_dir: Path) -> str:
    """The spec's ``mjcf:``/``urdf:`` value: the package reference, or the path relative to the spec's
    folder."""
    if model.reference.startswith((PACKAGE_SCHEME, MENAGERIE_SCHEME)):
        return model.reference
    return Path(os.path.relpath(model.path, spec_dir.resolve())).as_posix()


def _compile(source: MjcfSource, shown: str) -> mujoco.MjModel:
    try:
        return source.new_spec().compile()
    except ValueError as error:
        raise MjcfError(f"{shown}: MuJoCo refuses it: {' '.join(str(error).split())}") from None


def _read(
    path: Path, reference: str, fmt: Format, fixes: Sequence[MjcfFix], strict: bool = False
) -> tuple[MjcfSource, mujoco.MjModel, bool]:
    shown = display_path(path)
    if fmt == "mjcf":
        source = load_mjcf(reference, fixes)
        return source, _compile(source, shown), False
    source = load_urdf(reference)
    try:
        return source, source.new_spec().compile(), False
    except ValueError as error:
        if UNBALANCED_INERTIA not in str(error) or strict:
            repair = "; --strict: balance_inertia would repair it" if strict else ""
            raise MjcfError(f"{shown}: MuJoCo refuses it: {' '.join(str(error).split())}{repair}") from None
    balanced = load_urdf(reference, balance_inertia=True)
    return balanced, _compile(balanced, shown), True


def check_model_path(path: Path) -> Path:
    """``path`` resolved, if it is a file; :class:`MjcfError` saying what it is otherwise (missing,
    a folder, a FIFO, a device), before anything reads it."""
    kind = not_regular(path)
    if kind is not None:
        raise MjcfError(f"{display_path(path)}: {kind}; give an MJCF (.xml) or URDF (.urdf) file")
    resolved = path.resolve()
    if not is_file(resolved):
        raise MjcfError(f"{display_path(resolved)}: no such file; give an MJCF (.xml) or URDF (.urdf) file")
    return resolved


STRICT = "--strict refuses a file read with a value changed, left out or not finite"


def repairs(source: MjcfSource) -> list[str]:
    """The read's notes that say a value of the file was changed or left out (a visual of no size, a
    ``<mimic>`` MuJoCo ignores, a balanced inertia), which ``new --strict`` refuses."""
    return [
        note
        for note in source.notes
        if MUJOCO_IGNORES in note or NOT_FINITE in note or note.startswith("balance_inertia:")
    ]


def read_model_file(path: Path, fixes: Sequence[MjcfFix] = (), strict: bool = False) -> ModelFile:
    """The MJCF or URDF at ``path``, read as a spec naming it would read it (its own folder allowed
    when it is no package's; an MJCF repaired by ``fixes``), and compiled; ``strict``: refused when
    MuJoCo reads it only with a repair or a value left out (:func:`repairs`)."""
    path = check_model_path(path)
    fmt = file_format(path)
    package = python_package_reference(path) or menagerie.reference_of(path)
    if package is None and fmt == "urdf":  # a ROS package in a share/ tree (cmeel's example-robot-data)
        package = share_reference(path)
    reference = package or str(path)
    refused: MjcfError | None = None
    with allowing([] if package else [path.parent]), warnings.catch_warnings(record=True) as said:
        warnings.simplefilter("always")
        try:
            source, model, balanced = _read(path, reference, fmt, fixes, strict)
        except MjcfError as error:  # MuJoCo 3.9 refuses a NaN itself: the lines that say where stay
            refused = error
    for warning in said:  # a number that is not finite is refused below: said once, there
        if refused is not None or NOT_FINITE not in str(warning.message):
            warnings.warn(warning.message, warning.category, stacklevel=2)
    if refused is not None:
        raise refused
    changed = repairs(source) if strict else []
    if changed:
        raise MjcfError([Problem(f"{line}; {STRICT}") for line in changed])
    not_finite = [note for note in source.notes if NOT_FINITE in note]
    if not_finite:  # no home pose, servo or footprint can be read off a NaN
        raise MjcfError(
            [Problem(f"{line}; new reads a robot only from finite numbers") for line in not_finite]
        )
    return ModelFile(path, fmt, reference, source, model, balanced)
