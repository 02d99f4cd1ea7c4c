"""A spec's ``urdf:`` file -> the same :class:`~assembler.mjcf.source.MjcfSource` an MJCF file gives.

MuJoCo's own URDF compiler does the import (we write no URDF parser); :mod:`assembler.urdf.document`
prepares the text it reads and :mod:`assembler.urdf.postprocess` restores what it would lose. The
result is loaded once per process and re-read when the URDF or any of its meshes changes.

A spec's ``urdf: package://NAME/path`` names an installed Python package when ``NAME`` is one and
holds the file (as ``mjcf:`` does), otherwise a ROS package found as described in
:mod:`assembler.urdf.packages`.
"""

from __future__ import annotations

import functools
import warnings
import xml.etree.ElementTree as ET
from pathlib import Path

import mujoco

from assembler.errors import AssemblerWarning, MissingPackageError, MjcfError
from assembler.files.paths import (
    PACKAGE_SCHEME,
    allowed_folders,
    confine,
    display_path,
    homes_of,
    is_file,
    locate_model_file,
    package_root,
)
from assembler.mjcf import installed_mujoco
from assembler.mjcf.joints import Authored
from assembler.mjcf.source import GLOBAL_SECTIONS, MjcfSource, name_mesh_content_types
from assembler.mjcf.xml_guard import check_mjcf
from assembler.urdf.document import FORCED_COMPILER, Mimic, UrdfDocument, read_urdf
from assembler.urdf.mesh_formats import converted_dir
from assembler.urdf.packages import find_package_file, not_found_message, resolution_state, split_package_uri
from assembler.urdf.postprocess import (
    add_mimics,
    balance_inertias,
    exclude_welded_parents,
    robosuite_groups,
    set_limits,
)

DEFAULT_INTEGRATOR = "implicitfast"
"""The integrator of a robot made from a URDF, unless its ``<mujoco><option>`` names another."""

DYNAMICS_ATTRIBUTES: dict[str, str] = {"damping": "damping", "friction": "frictionloss"}
"""URDF ``<dynamics>`` attribute -> the MuJoCo joint attribute MuJoCo's import sets from it."""


def _python_package_file(reference: str) -> Path | None:
    """The file in the installed Python package the reference names, if it holds one; a path out of
    the package is refused first, so the answer is the same whether or not that file exists."""
    name, _, inner = reference[len(PACKAGE_SCHEME) :].partition("/")
    root = package_root(name) if name.isidentifier() else None
    if root is None:
        return None
    path = confine(root / inner, [root], f"{reference}: ", MjcfError)
    return path if is_file(path) else None


def locate_urdf_file(reference: str) -> Path:
    """The URDF file behind a spec's resolved ``urdf`` reference, confined to its home."""
    if not reference.startswith(PACKAGE_SCHEME):
        return locate_model_file(reference)
    in_python_package = _python_package_file(reference)
    if in_python_package is not None:
        return in_python_package
    found = find_package_file(reference, what=f"{reference}: ")
    if found is None:
        parts = split_package_uri(reference)
        message = not_found_message(reference)
        if parts is not None and " not found " in message:
            raise MissingPackageError(message, parts[0])
        raise MjcfError(message)
    return found[0]  # confined to its package by find_package_file


def _globals_xml(document: UrdfDocument) -> str:
    skeleton = ET.Element("mujoco", {"model": document.robot_name})
    compiler = ET.SubElement(skeleton, "compiler", {"angle": "radian"})
    own = document.mujoco_element.find("compiler")
    for name, value in (own.attrib if own is not None else {}).items():
        if name not in FORCED_COMPILER and name != "angle":
            compiler.set(name, value)
    for tag in GLOBAL_SECTIONS[1:]:
        element = document.mujoco_element.find(tag)
        if element is not None:
            skeleton.append(element)
    option = skeleton.find("option")
    if option is None:
        option = ET.SubElement(skeleton, "option")
    # A URDF gives no integrator; position servos with velocity gains need an implicit one to be
    # stable at MuJoCo's default time step (the menagerie's models all choose implicitfast).
    option.set("integrator", option.get("integrator", DEFAULT_INTEGRATOR))
    return ET.tostring(skeleton, encoding="unicode")


def _authored(spec: mujoco.MjSpec, document: UrdfDocument) -> tuple[Authored, ...]:
    """Per joint, the attributes the URDF sets (``<dynamics>``), as the joint rules need them."""
    return tuple(
        {DYNAMICS_ATTRIBUTES[a]: ("urdf <dynamics>", "") for a in document.dynamics.get(joint.name, ())}
        for joint in spec.joints
    )


def _ignored(document: UrdfDocument) -> list[str]:
    """One line per child of the URDF's ``<mujoco>`` element that nothing reads."""
    shown = display_path(document.path)
    return [
        f"{shown}:{line}: <mujoco><{tag}> is ignored: a URDF's <mujoco> element gives only "
        f"{', '.join(f'<{t}>' for t in GLOBAL_SECTIONS)}; say the rest in the spec (actuators:, joints:) "
        "or in an MJCF file"
        for tag, line in document.ignored
    ]


def _notes(document: UrdfDocument, balanced: list[str], ignored: dict[Mimic, str]) -> tuple[str, ...]:
    notes = [f"the URDF's compiler {setting} was replaced" for setting in document.overridden]
    notes += _ignored(document)
    notes += [f"balance_inertia: {line}" for line in balanced]
    notes += [
        f"<mimic> {m.follower} = {m.multiplier:g} * {m.leader} + {m.offset:g} is a joint equality"
        for m in document.mimics
        if m not in ignored
    ]
    notes += ignored.values()
    notes += document.discarded
    notes += document.non_finite
    made = [file for file in document.mesh_files if file.parent == converted_dir()]
    converted = [file for file in made if file not in document.renamed]
    if converted:
        notes.append(f"{len(converted)} mesh file(s) converted to OBJ in {display_path(converted_dir())}")
    if document.renamed:
        notes.append(
            f"{len(document.renamed)} mesh file(s) whose name another mesh has copied under a distinct "
            f"name to {display_path(converted_dir())} (MuJoCo before 4.0 would use one mesh for both)"
        )
    return tuple(notes)


def _stat(path: Path) -> tuple[str, int, int]:
    stat = path.stat()
    return str(path), stat.st_size, stat.st_mtime_ns


def _import(text: str, shown: str) -> mujoco.MjSpec:
    """MuJoCo's own import of the prepared URDF text."""
    try:
        return mujoco.MjSpec.from_string(text)
    except ValueError as error:
        raise MjcfError(f"{shown}: MuJoCo cannot read it: {' '.join(str(error).split())}") from None


@functools.lru_cache(maxsize=32)
def _load(
    path: Path,
    mtime_ns: int,
    size: int,
    homes: frozenset[Path],
    converted: Path,
    balance: bool,
    packages: tuple[object, ...],
) -> MjcfSource:
    shown = display_path(path)
    check_mjcf(path, homes)  # size and no DTD, before any parser expands anything
    before = _stat(path)
    document = read_urdf(path, homes, path.read_bytes())
    # MuJoCo's warnings are said to the user, never appended to MUJOCO_LOG.TXT; when our own check
    # says the same thing (a <mimic> MuJoCo 4 ignores with a warning), ours, with the file's line, is enough.
    with installed_mujoco.warned(shown) as said:
        spec = _import(document.text, shown)
        ignored = add_mimics(spec, document.mimics, shown)
        said += [f"<mimic> on joint '{mimic.follower}' ignored" for mimic in ignored]  # ours has its line
    set_limits(spec, document)
    robosuite_groups(spec)
    name_mesh_content_types(spec)  # the XML of a cached and an uncached build alike
    exclude_welded_parents(spec)
    balanced = balance_inertias(spec) if balance else []
    unnamed = [j for j in spec.joints if not j.name and j.type != mujoco.mjtJoint.mjJNT_FREE]
    if unnamed:
        raise MjcfError(f"{shown}: every joint needs a name")
    # said once per version of the file, as MuJoCo's own warnings are
    # balanced inertias are the spec's own choice (balance_inertia: true), kept in the notes (and in the
    # comment new writes above that line), not said at every read
    for line in [*_ignored(document), *ignored.values(), *document.discarded, *document.non_finite]:
        warnings.warn(line, AssemblerWarning, stacklevel=2)
    files = (before, *(_stat(file) for file in dict.fromkeys(document.mesh_files)))
    return MjcfSource(
        path=path,
        pristine=spec,
        globals_xml=_globals_xml(document),
        authored=_authored(spec, document),
        files=files,
        velocity_limits=dict(document.velocity_limits),
        notes=_notes(document, balanced, ignored),
    )


def load_urdf(reference: str, balance_inertia: bool = False) -> MjcfSource:
    """The robot behind a spec's ``urdf`` reference, as MuJoCo imports it with the traps disarmed
    (and link inertias that violate A + B >= C balanced, if asked)."""
    path = locate_urdf_file(reference).resolve()
    stat = path.stat()
    homes = frozenset({path.parent, *homes_of(path), *allowed_folders()})
    # ``packages``: where package:// leads is part of the read, or a switched ROS_PACKAGE_PATH would
    # get the other copy's meshes (and the disk cache would keep that model under the new key)
    packages = resolution_state(path)
    arguments = (path, stat.st_mtime_ns, stat.st_size, homes, converted_dir(), balance_inertia, packages)
    source = _load(*arguments)
    if not source.is_current():  # a mesh changed or a converted mesh was removed: read it again
        _load.cache_clear()
        source = _load(*arguments)
    return source
