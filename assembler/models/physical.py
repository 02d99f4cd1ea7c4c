"""A part's ``bodies:`` and ``geoms:`` entries resolved against its model file, and applied to its MjSpec.

Resolution follows ``joints:``: each entry matches names or globs (a miss is an error at the
entry's line listing what exists), entries apply in order and a later one replaces an earlier
one's value on the same element. Each final value keeps the index of the entry that gave it, for
``assembler inspect``. Application edits a fresh copy of the part's prepared spec before it is
attached, so every name is still the file's own.

Size scaling by S scales, in the body's frame: its geoms (position, size, ``fromto``), meshes
(their ``scale``), sites' positions, joint anchors, cameras, lights, frames and child bodies'
offsets, and its inertial frame's position. A site moves with its body and keeps its size, which
nothing in the physics reads (a frame, a marker, an IMU), unless it is a sensor's zone (a touch
sensor's or a contact sensor's site: :func:`zone_sites`), whose size is scaled with the geoms it
covers; the patch and MuJoCo Warp batches follow the same rule. The mass factor is ``mass_scale``
or S^3; the inertia factor is the mass factor times S^2. A body without an ``<inertial>`` gets its
mass from its geoms: their densities (or masses, where the file gives them) are scaled instead.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass, field

import mujoco
import numpy as np

from assembler.errors import Problem
from assembler.mjcf.census import scaled_size
from assembler.models.joint_rules import SpecProblem, matching_joints, no_match
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import BodyScale, GeomFriction


@dataclass(frozen=True)
class PhysicalValue:
    """A factor or a friction and the spec entry (``bodies[i]``, ``geoms[i]``) that gave it."""

    value: float | tuple[float, float, float]
    section: str
    """``bodies`` or ``geoms``."""

    index: int
    """The entry's index in its section."""

    @property
    def entry(self) -> str:
        """``bodies[i]`` or ``geoms[i]``."""
        return f"{self.section}[{self.index}]"

    def __str__(self) -> str:
        return f"spec {self.entry}"


@dataclass
class PhysicalTable:
    """Body -> factor name -> value, and geom -> friction, as the spec's entries resolve them."""

    bodies: dict[str, dict[str, PhysicalValue]] = field(default_factory=dict)
    geoms: dict[str, PhysicalValue] = field(default_factory=dict)

    def factors(self, body: str) -> tuple[float, float, float]:
        """(size factor S, mass factor, inertia factor) of ``body``; (1, 1, 1) when no entry names it."""
        values = self.bodies.get(body, {})
        size = float(values["size_scale"].value) if "size_scale" in values else 1.0  # type: ignore[arg-type]
        mass = float(values["mass_scale"].value) if "mass_scale" in values else size**3  # type: ignore[arg-type]
        return size, mass, mass * size**2


def _named(elements: Sequence[mujoco.MjsBody] | Sequence[mujoco.MjsGeom]) -> list[str]:
    return [element.name for element in elements if element.name]


def element_names(mjspec: mujoco.MjSpec) -> tuple[list[str], list[str]]:
    """The named bodies (the world excluded) and named geoms of a part's spec, in file order."""
    return _named(mjspec.bodies[1:]), _named(mjspec.geoms)


def resolve_physical(
    mjspec: mujoco.MjSpec,
    bodies: Sequence[BodyScale],
    geoms: Sequence[GeomFriction],
    problem: SpecProblem,
    names: tuple[list[str], list[str]] | None = None,
) -> tuple[PhysicalTable, list[Problem]]:
    """Each named body's factors and each named geom's friction; the entries matching nothing.
    ``names``: :func:`element_names` of ``mjspec``, when the caller has them."""
    table = PhysicalTable()
    problems: list[Problem] = []
    body_names, geom_names = names if names is not None else element_names(mjspec)
    for index, entry in enumerate(bodies):
        matched = matching_joints(entry.match, body_names)
        if not matched:
            here = FieldPath(("bodies", index, "match"))
            problems.append(problem(here, no_match(entry.match, body_names, "body", "bodies")))
        for name in matched:
            for factor, value in entry.values().items():
                table.bodies.setdefault(name, {})[factor] = PhysicalValue(value, "bodies", index)
    for index, friction in enumerate(geoms):
        matched = matching_joints(friction.match, geom_names)
        if not matched:
            here = FieldPath(("geoms", index, "match"))
            problems.append(problem(here, no_match(friction.match, geom_names, "geom")))
        for name in matched:
            table.geoms[name] = PhysicalValue(friction.friction, "geoms", index)
    if any(table.factors(body)[0] != 1.0 for body in table.bodies):  # only a size factor scales meshes
        problems += _shared_mesh_problems(mjspec, table, problem)
    return table, problems


def _shared_mesh_problems(mjspec: mujoco.MjSpec, table: PhysicalTable, problem: SpecProblem) -> list[Problem]:
    """A mesh is scaled as a whole: every body using it must have the same size factor."""
    users: dict[str, dict[float, str]] = {}
    for geom in mjspec.geoms:
        if geom.type == mujoco.mjtGeom.mjGEOM_MESH and geom.meshname:
            body = geom.parent.name
            users.setdefault(geom.meshname, {}).setdefault(table.factors(body)[0], body)
    problems = []
    for mesh, by_scale in users.items():
        if len(by_scale) > 1:
            (s1, b1), (s2, b2) = list(by_scale.items())[:2]
            entry = table.bodies.get(b1 if s1 != 1.0 else b2, {}).get("size_scale")
            where = FieldPath(("bodies", entry.index if entry else 0, "size_scale"))
            message = (
                f"mesh '{mesh}' is used by bodies '{b1}' (size_scale {s1:g}) and '{b2}' (size_scale {s2:g}); "
                "a mesh is scaled as a whole: give these bodies the same size_scale"
            )
            problems.append(problem(where, message))
    return problems


def _scale_vector(element: object, attribute: str, factor: float) -> None:
    setattr(element, attribute, np.asarray(getattr(element, attribute), dtype=float) * factor)


def _scale_fromto(element: mujoco.MjsGeom | mujoco.MjsSite, factor: float) -> None:
    if not math.isnan(element.fromto[0]):
        _scale_vector(element, "fromto", factor)


ZONE_SENSORS: frozenset[int] = frozenset(
    int(getattr(mujoco.mjtSensor, name))
    for name in ("mjSENS_TOUCH", "mjSENS_CONTACT")
    if hasattr(mujoco.mjtSensor, name)
)
"""Sensors whose site is a zone (a volume they read contacts in): its size follows a size_scale."""


def zone_sites(mjspec: mujoco.MjSpec) -> set[str]:
    """The sites of ``mjspec`` that are a sensor's zone (:data:`ZONE_SENSORS`)."""
    site = mujoco.mjtObj.mjOBJ_SITE
    zones = set()
    for sensor in mjspec.sensors:
        if int(sensor.type) in ZONE_SENSORS:
            zones |= {
                name
                for kind, name in ((sensor.objtype, sensor.objname), (sensor.reftype, sensor.refname))
                if kind == site
            }
    return zones


def _move_site(site: mujoco.MjsSite, factor: float) -> None:
    """A site's position scaled, its size kept (a ``fromto`` moves its middle, keeping its length)."""
    _scale_vector(site, "pos", factor)
    if not math.isnan(site.fromto[0]):
        ends = np.asarray(site.fromto, dtype=float).reshape(2, 3)
        middle, half = ends.mean(axis=0), (ends[1] - ends[0]) / 2
        site.fromto = np.concatenate([middle * factor - half, middle * factor + half])


def _scale_body(body: mujoco.MjsBody, size: float, mass: float, inertia: float, zones: set[str]) -> None:
    if size != 1.0:
        for element in [*body.geoms, *(s for s in body.sites if s.name in zones)]:
            _scale_vector(element, "pos", size)
            element.size = scaled_size(element.size, int(element.type), size)
            _scale_fromto(element, size)
        for site in body.sites:
            if site.name not in zones:
                _move_site(site, size)
        for group in (body.joints, body.cameras, body.lights, body.frames, body.bodies):
            for element in group:
                _scale_vector(element, "pos", size)
    if body.explicitinertial:
        _scale_vector(body, "ipos", size)
        body.mass *= mass
        _scale_vector(body, "inertia", inertia)
        if not math.isnan(body.fullinertia[0]):
            _scale_vector(body, "fullinertia", inertia)
        return
    for geom in body.geoms:  # the compiler derives this body's mass and inertia from its geoms
        if math.isnan(geom.mass):
            geom.density *= mass / size**3
        else:
            geom.mass *= mass


def apply_physical(mjspec: mujoco.MjSpec, table: PhysicalTable) -> None:
    """Scale the bodies and set the geom frictions ``table`` gives, on a part's unattached spec."""
    scaled_meshes: set[str] = set()
    zones = zone_sites(mjspec) if table.bodies else set()
    for name in table.bodies:
        body = mjspec.body(name)
        size, mass, inertia = table.factors(name)
        _scale_body(body, size, mass, inertia, zones)
        for geom in body.geoms:
            if geom.type == mujoco.mjtGeom.mjGEOM_MESH and geom.meshname not in scaled_meshes and size != 1.0:
                scaled_meshes.add(geom.meshname)  # shared meshes have one factor (resolve_physical checks)
                _scale_vector(mjspec.mesh(geom.meshname), "scale", size)
    for name, friction in table.geoms.items():
        mjspec.geom(name).friction = np.asarray(friction.value, dtype=float)
