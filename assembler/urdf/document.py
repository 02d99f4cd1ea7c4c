"""A URDF file read for MuJoCo: mesh URIs resolved, unreadable meshes converted, traps disarmed.

MuJoCo's URDF reader strips every mesh path to its bare file name (``package://`` URIs included),
discards visual geoms and fuses bodies without joints into their parents (a fixed base link
vanishes into the world) unless told otherwise. So before MuJoCo sees the text we:

- replace each mesh ``filename`` by the absolute path of a file it can read (see
  :mod:`assembler.urdf.packages` and :mod:`assembler.urdf.mesh_formats`), each confined to its home;
- set ``<mujoco><compiler discardvisual="false" fusestatic="false" strippath="false"/></mujoco>``
  (MuJoCo's URDF extension element), keeping any other compiler setting the URDF gives;
- record what MuJoCo does not carry over: joint velocity limits, ``<mimic>`` couplings, which
  joints declare ``<dynamics>``, and the line of each, for messages.
"""

from __future__ import annotations

import math
import os
import xml.etree.ElementTree as ET
from collections.abc import Collection
from dataclasses import dataclass, field
from pathlib import Path

from assembler.errors import MjcfError, Problem
from assembler.files.paths import confine, display_path, is_file
from assembler.files.regular import not_regular
from assembler.mjcf.source import GLOBAL_SECTIONS
from assembler.mjcf.xml_guard import non_finite_values
from assembler.urdf.mesh_formats import MeshConversionError, check_mesh_format, readable_mesh, renamed_copy
from assembler.urdf.outline import outline
from assembler.urdf.packages import find_package_file, not_found_message, split_package_uri

FORCED_COMPILER: dict[str, str] = {"discardvisual": "false", "fusestatic": "false", "strippath": "false"}
"""Compiler settings MuJoCo's URDF import needs to keep visual geoms, a fixed base link, and paths."""

DIRECTORY_ATTRIBUTES: tuple[str, ...] = ("meshdir", "texturedir", "assetdir")

EXTENSION_SECTIONS: frozenset[str] = frozenset(GLOBAL_SECTIONS)
"""Children of a URDF's ``<mujoco>`` element that are read (``<compiler>`` settings are kept, the
others become the robot's own global sections); any other is ignored, and said to be."""


@dataclass(frozen=True)
class Mimic:
    """A URDF ``<mimic>``: ``follower = multiplier * leader + offset``."""

    follower: str
    leader: str
    multiplier: float
    offset: float
    line: int


@dataclass
class UrdfDocument:
    """The URDF text to hand MuJoCo and what the URDF says that MuJoCo does not keep."""

    path: Path
    text: str
    robot_name: str
    mujoco_element: ET.Element
    """The ``<mujoco>`` extension element, with the forced compiler settings."""
    overridden: list[str] = field(default_factory=list)
    """Compiler settings of the URDF itself that we replaced, as ``name="value"``."""
    mesh_files: list[Path] = field(default_factory=list)
    """Every mesh file read (originals, before conversion) and every converted or renamed copy."""
    renamed: list[Path] = field(default_factory=list)
    """Copies of mesh files whose stem another mesh file of the URDF has (see assembler.urdf.mesh_formats)."""
    homes: set[Path] = field(default_factory=set)
    """Folders the meshes were admitted from (package folders found for package:// URIs)."""
    velocity_limits: dict[str, float] = field(default_factory=dict)
    mimics: list[Mimic] = field(default_factory=list)
    dynamics: dict[str, set[str]] = field(default_factory=dict)
    """Joint -> the ``<dynamics>`` attributes it sets (damping, friction)."""
    limited: dict[str, bool] = field(default_factory=dict)
    """Joint -> whether its ``<limit>`` bounds its position (revolute and prismatic with lower < upper)."""
    efforts: dict[str, float] = field(default_factory=dict)
    ignored: list[tuple[str, int]] = field(default_factory=list)
    """``(tag, line)`` of each child of ``<mujoco>`` that neither MuJoCo's import nor we read."""
    non_finite: list[str] = field(default_factory=list)
    """One line per attribute holding a number that is not finite (``nan``, ``inf``), which MuJoCo keeps."""
    discarded: list[str] = field(default_factory=list)
    """One line per ``<visual>`` left out because MuJoCo could not compile it (a size that is not
    positive), which MuJoCo's own import never compiles (it discards visuals)."""


MESH_PATHS: tuple[str, ...] = ("link/visual/geometry/mesh", "link/collision/geometry/mesh")

SIZE_ATTRIBUTES: dict[str, tuple[str, ...]] = {
    "sphere": ("radius",),
    "box": ("size",),
    "cylinder": ("radius", "length"),
    "capsule": ("radius", "length"),
}
"""The size attributes of each URDF shape."""


def _bad_size(visual: ET.Element) -> str | None:
    """``radius="0.0"`` for a visual whose shape has a size that is not a positive number, else None."""
    for shape in visual.findall("geometry/*"):
        for attribute in SIZE_ATTRIBUTES.get(shape.tag, ()):
            text = shape.get(attribute, "")
            try:
                values = [float(v) for v in text.split()]
            except ValueError:
                continue  # MuJoCo's import says what it cannot read
            if any(not math.isfinite(v) or v <= 0 for v in values):
                return f'<{shape.tag} {attribute}="{text}">'
    return None


def _discard_bad_visuals(root: ET.Element, lines: list[int], shown: str, document: UrdfDocument) -> None:
    """Leave out each ``<visual>`` of a size MuJoCo cannot compile (pybullet's Laikago marks its toes
    with ``<sphere radius="0.0"/>``), saying so: MuJoCo's own import discards visuals, so it loads."""
    visuals = [(link, visual) for link in root.findall("link") for visual in link.findall("visual")]
    for (link, visual), line in zip(visuals, lines, strict=True):
        bad = _bad_size(visual)
        if bad is not None:
            link.remove(visual)
            document.discarded.append(
                f"{shown}:{line}: the <visual> of link '{link.get('name')}' is {bad}, not a positive size: "
                "left out, as MuJoCo's URDF import leaves out every visual"
            )


"""Where the meshes MuJoCo reads sit (meshes of ``<gazebo>`` and other tool sections are left alone)."""


def _number(text: str | None, default: float) -> float:
    try:
        return float(text) if text is not None else default
    except ValueError:
        return default


class _Reader:
    """Collects the problems of one URDF (each mesh file reported once) while rewriting it."""

    def __init__(self, path: Path, homes: Collection[Path], lines: dict[str, list[int]]) -> None:
        self.path = path
        self.shown = display_path(path)
        self.homes = {path.parent, *homes}
        self.lines = lines
        self.problems: list[Problem] = []
        self.resolved: dict[str, str] = {}  # filename as written -> file MuJoCo reads
        self.reported: set[str] = set()
        self.stems: dict[str, Path] = {}  # MuJoCo names a URDF mesh after its file's stem

    def problem(self, line: int, message: str) -> None:
        self.problems.append(Problem(f"{self.shown}:{line}: {message}"))

    def _confined(self, written: str, line: int, directory: str, document: UrdfDocument) -> Path | None:
        """The mesh file ``written`` names, confined to its home before its existence is looked at
        (a refusal is the same whether or not the file exists); None, reported, if it is missing."""
        where = f"{self.shown}:{line}: mesh "
        if split_package_uri(written) is not None:
            found = find_package_file(written, self.path, f"{where}{written}: ")
            if found is None:
                self.problem(line, f"mesh {not_found_message(written, self.path)}")
                return None
            file, home = found
            document.homes.add(home)
            return file
        name = written.removeprefix("file://")
        file = confine(
            Path(name) if os.path.isabs(name) else self.path.parent / directory / name,
            self.homes,
            where,
            MjcfError,
        )
        if not is_file(file):
            kind = not_regular(file)  # a FIFO or a folder: say what it is
            self.problem(
                line,
                f"mesh {display_path(file)}: {kind}"
                if kind
                else f"mesh file not found: {display_path(file)}",
            )
            return None
        return file

    def mesh_file(self, written: str, line: int, directory: str, document: UrdfDocument) -> str | None:
        if written in self.resolved:
            return self.resolved[written]
        if written in self.reported:
            return None
        self.reported.add(written)
        try:
            check_mesh_format(Path(written.removeprefix("file://")), f"mesh {written}")  # before any lookup
            file = self._confined(written, line, directory, document)
            if file is None:
                return None
            readable = readable_mesh(file)
        except MjcfError as error:
            self.problems.extend(error.problems)
            return None
        except MeshConversionError as error:
            self.problem(line, str(error))
            return None
        if self.stems.setdefault(readable.stem, readable) != readable:
            readable = renamed_copy(readable)
            document.renamed.append(readable)
        document.mesh_files += [file] if readable == file else [file, readable]
        self.resolved[written] = str(readable)
        return str(readable)


def _joint_facts(root: ET.Element, lines: list[int], document: UrdfDocument) -> None:
    for joint, line in zip(root.findall("joint"), lines, strict=True):
        name, kind = joint.get("name", ""), joint.get("type", "")
        limit = joint.find("limit")
        if limit is not None:
            velocity = _number(limit.get("velocity"), 0.0)
            effort = _number(limit.get("effort"), 0.0)
            if velocity > 0:
                document.velocity_limits[name] = velocity
            if effort > 0:
                document.efforts[name] = effort
            lower, upper = _number(limit.get("lower"), 0.0), _number(limit.get("upper"), 0.0)
            document.limited[name] = kind in ("revolute", "prismatic") and lower < upper
        dynamics = joint.find("dynamics")
        if dynamics is not None:
            document.dynamics[name] = {a for a in ("damping", "friction") if dynamics.get(a) is not None}
        mimic = joint.find("mimic")
        if mimic is not None:
            document.mimics.append(
                Mimic(
                    follower=name,
                    leader=mimic.get("joint", ""),
                    multiplier=_number(mimic.get("multiplier"), 1.0),
                    offset=_number(mimic.get("offset"), 0.0),
                    line=line,
                )
            )


def _extension(root: ET.Element, document: UrdfDocument) -> tuple[ET.Element, str]:
    """The ``<mujoco>`` element with the forced compiler settings; returns it and its meshdir."""
    extension = root.find("mujoco")
    if extension is None:
        extension = ET.SubElement(root, "mujoco")
    compiler = extension.find("compiler")
    if compiler is None:
        compiler = ET.SubElement(extension, "compiler")
    for name, value in FORCED_COMPILER.items():
        if compiler.get(name) not in (None, value):
            document.overridden.append(f'{name}="{compiler.get(name)}"')
        compiler.set(name, value)
    directory = compiler.get("meshdir", "")
    for name in DIRECTORY_ATTRIBUTES:
        compiler.attrib.pop(name, None)  # every mesh path is absolute now
    return extension, directory


def read_urdf(path: Path, homes: Collection[Path], data: bytes) -> UrdfDocument:
    """The URDF at ``path`` (its bytes ``data``, already checked) made ready for MuJoCo."""
    shown = display_path(path)
    found = outline(
        data, shown, (*MESH_PATHS, "joint", "link/visual")
    )  # limits and repeated names, before a tree is built
    try:
        root = ET.fromstring(data)
    except ET.ParseError as error:
        raise MjcfError(f"{shown}: not well-formed XML: {error}") from None
    if root.tag != "robot":
        raise MjcfError(f"{shown}: not a URDF file: the root element is <{root.tag}>, expected <robot>")
    document = UrdfDocument(path, "", root.get("name") or path.stem, ET.Element("mujoco"))
    extension, directory = _extension(root, document)
    reader = _Reader(path, homes, found.lines)
    meshes = [
        (mesh, line)
        for path in MESH_PATHS
        for mesh, line in zip(root.findall(path), reader.lines[path], strict=True)
    ]
    for mesh, line in sorted(meshes, key=lambda pair: pair[1]):
        written = mesh.get("filename", "")
        resolved = reader.mesh_file(written, line, directory, document) if written else None
        if resolved is not None:
            mesh.set("filename", resolved)
    if reader.problems:
        raise MjcfError(reader.problems)
    _joint_facts(root, reader.lines["joint"], document)
    _discard_bad_visuals(root, reader.lines["link/visual"], shown, document)
    document.non_finite = non_finite_values(data, shown, "the URDF")
    document.mujoco_element = extension
    document.ignored = [(tag, line) for tag, line in found.extension if tag not in EXTENSION_SECTIONS]
    document.text = ET.tostring(root, encoding="unicode")
    return document
