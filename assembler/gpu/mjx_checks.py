"""RA811-RA815 (``assembler lint --target mjx``): what MJX (its JAX implementation) refuses or runs badly.

The kinds and collision pairs are those ``mujoco.mjx.put_model`` (mujoco-mjx 3.17.0) raises
``NotImplementedError`` for: its enums (``mujoco/mjx/_src/types.py``) and its table of collision
functions (``collision_driver._COLLISION_FUNC``); tests/tools/test_gpu_lint.py keeps these tables
equal to them. The mesh sizes are those MJX's documentation asks for ("The Sharp Bits": about 200
hull vertices against primitives, fewer than 32 between two meshes).
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.gpu.engines import (
    KindTable,
    collidable_pairs,
    geom_type_name,
    option_finding,
    refused_elements,
    refused_solver_and_enable_flags,
)

MJX_COLLISION_PAIRS: frozenset[tuple[str, str]] = frozenset(
    {
        ("PLANE", "SPHERE"),
        ("PLANE", "CAPSULE"),
        ("PLANE", "BOX"),
        ("PLANE", "ELLIPSOID"),
        ("PLANE", "CYLINDER"),
        ("PLANE", "MESH"),
        ("HFIELD", "SPHERE"),
        ("HFIELD", "CAPSULE"),
        ("HFIELD", "BOX"),
        ("HFIELD", "MESH"),
        ("SPHERE", "SPHERE"),
        ("SPHERE", "CAPSULE"),
        ("SPHERE", "CYLINDER"),
        ("SPHERE", "ELLIPSOID"),
        ("SPHERE", "BOX"),
        ("SPHERE", "MESH"),
        ("CAPSULE", "CAPSULE"),
        ("CAPSULE", "BOX"),
        ("CAPSULE", "ELLIPSOID"),
        ("CAPSULE", "CYLINDER"),
        ("CAPSULE", "MESH"),
        ("ELLIPSOID", "ELLIPSOID"),
        ("ELLIPSOID", "CYLINDER"),
        ("CYLINDER", "CYLINDER"),
        ("BOX", "BOX"),
        ("BOX", "MESH"),
        ("MESH", "MESH"),
    }
)
"""Geom type pairs (lower type first, as ``mjtGeom`` orders them) MJX has a collision function for;
missing: box-cylinder, box-ellipsoid, cylinder-mesh, ellipsoid-mesh, heightfield-cylinder/ellipsoid."""

MJX_ELEMENT_KINDS: tuple[KindTable, ...] = (
    KindTable("actuator_trntype", "mjtTrn", ("mjTRN_SLIDERCRANK", "mjTRN_BODY", "mjTRN_SO3")),
    KindTable("actuator_dyntype", "mjtDyn", ("mjDYN_DCMOTOR", "mjDYN_PID", "mjDYN_USER")),
    KindTable("actuator_gaintype", "mjtGain", ("mjGAIN_DCMOTOR", "mjGAIN_SO3", "mjGAIN_PID", "mjGAIN_USER")),
    KindTable("actuator_biastype", "mjtBias", ("mjBIAS_DCMOTOR", "mjBIAS_SO3", "mjBIAS_USER")),
    KindTable("eq_type", "mjtEq", ("mjEQ_FLEX", "mjEQ_FLEXVERT", "mjEQ_FLEXSTRAIN", "mjEQ_DISTANCE")),
    KindTable(
        "sensor_type",
        "mjtSensor",
        (
            "mjSENS_JOINTLIMITPOS",
            "mjSENS_JOINTLIMITVEL",
            "mjSENS_JOINTLIMITFRC",
            "mjSENS_TENDONLIMITPOS",
            "mjSENS_TENDONLIMITVEL",
            "mjSENS_TENDONLIMITFRC",
            "mjSENS_INSIDESITE",
            "mjSENS_GEOMDIST",
            "mjSENS_GEOMNORMAL",
            "mjSENS_GEOMFROMTO",
            "mjSENS_E_POTENTIAL",
            "mjSENS_E_KINETIC",
            "mjSENS_PLUGIN",
            "mjSENS_USER",
        ),
    ),
)
"""Element kinds MJX has no implementation of (adhesion actuators are mjTRN_BODY)."""

MJX_INTEGRATORS_REFUSED: tuple[str, ...] = ("mjINT_IMPLICIT",)
MJX_SOLVERS_REFUSED: tuple[str, ...] = ("mjSOL_PGS",)
MJX_ENABLE_REFUSED: tuple[str, ...] = (
    "mjENBL_OVERRIDE",
    "mjENBL_ENERGY",
    "mjENBL_FWDINV",
    "mjENBL_DIAGEXACT",
    "mjENBL_SPECULATIVE",
)

ELEMENT_FIX = {
    "actuator": "use a <motor>, <position>, <velocity> or <general> actuator on a joint or tendon "
    "(an adhesion actuator has no MJX counterpart)",
    "eq": "express the constraint as a connect, weld, joint or tendon equality",
    "sensor": "drop the sensor and compute the quantity from qpos/qvel in your environment",
}

HULL_VERTICES_WITH_PRIMITIVES = 200
"""MJX's documentation: a convex mesh colliding with primitives should have about 200 vertices or less."""

HULL_VERTICES_WITH_MESHES = 32
"""MJX's documentation: a convex mesh colliding with another mesh should have fewer than 32 vertices."""

MESH, HFIELD = int(mujoco.mjtGeom.mjGEOM_MESH), int(mujoco.mjtGeom.mjGEOM_HFIELD)
GEOM, BODY = mujoco.mjtObj.mjOBJ_GEOM, mujoco.mjtObj.mjOBJ_BODY


def mjx_refused_options(target: LintTarget) -> Iterator[Finding]:
    """RA812 (error): an integrator, solver or enable flag MJX's put_model refuses."""
    option = target.model.opt
    integrator = mujoco.mjtIntegrator(int(option.integrator)).name
    if integrator in MJX_INTEGRATORS_REFUSED:
        fix = 'set <option integrator="implicitfast"/> (or "Euler", "RK4")'
        yield option_finding(target, "RA812", "mjx", f"integrator {integrator}", fix)
    yield from refused_solver_and_enable_flags(
        target, "RA812", "mjx", MJX_SOLVERS_REFUSED, MJX_ENABLE_REFUSED
    )
    fluid = option.density > 0 or option.viscosity > 0 or bool(option.wind.any())
    if integrator == "mjINT_IMPLICITFAST" and fluid:
        fix = 'set <option integrator="Euler"/>, or density="0" viscosity="0" and no wind'
        yield option_finding(target, "RA812", "mjx", "integrator implicitfast with fluid drag", fix)


def mjx_refused_elements(target: LintTarget) -> Iterator[Finding]:
    """RA813 (error): flex, or an actuator, equality or sensor kind MJX's put_model refuses."""
    for table in MJX_ELEMENT_KINDS:
        fix = ELEMENT_FIX[table.field.split("_")[0]]
        yield from refused_elements(target, table, "RA813", "mjx", fix)
    if target.model.nflex:
        yield Finding(
            code="RA813",
            severity="error",
            subject=target.name,
            why=f"{target.model.nflex} flex object(s): MJX's put_model refuses flex (NotImplementedError)",
            fix="use MuJoCo Warp (assembler lint --target mjwarp), or model the soft part with rigid bodies",
        )


def _pair_subject(target: LintTarget, first: int, second: int) -> tuple[str, str]:
    names = [target.element_name(GEOM, g) for g in (first, second)]
    bodies = [target.element_name(BODY, int(target.model.geom_bodyid[g])) for g in (first, second)]
    kinds = [geom_type_name(target.model, g) for g in (first, second)]
    described = f"{kinds[0]} {names[0]} (body {bodies[0]}) and {kinds[1]} {names[1]} (body {bodies[1]})"
    return f"{names[0]} / {names[1]}", described


def mjx_missing_collisions(target: LintTarget) -> Iterator[Finding]:
    """RA811 (error): geoms that can collide are of types MJX has no collision function for.

    Every missing pair has a cylinder or an ellipsoid in it; one finding per such geom and partner
    type, naming the partners, since that geom is the one to change.
    """
    model = target.model
    partners: dict[tuple[int, tuple[str, str]], list[int]] = {}
    for first, second, _ in collidable_pairs(model):
        types = tuple(
            mujoco.mjtGeom(int(model.geom_type[g])).name.removeprefix("mjGEOM_") for g in (first, second)
        )
        if types in MJX_COLLISION_PAIRS:
            continue
        odd, other = (first, second) if types[0] in ("CYLINDER", "ELLIPSOID") else (second, first)
        partners.setdefault((odd, (types[0], types[1])), []).append(other)
    for (odd, types), others in partners.items():
        name = target.element_name(GEOM, odd)
        body = target.element_name(BODY, int(model.geom_bodyid[odd]))
        kind = geom_type_name(model, odd)
        other_kind = geom_type_name(model, others[0])
        shown = ", ".join(target.element_name(GEOM, g) for g in others[:3])
        more = f" and {len(others) - 3} more" if len(others) > 3 else ""
        shape = "a capsule" if kind == "cylinder" else "a sphere or capsule"
        yield Finding(
            code="RA811",
            severity="error",
            subject=name,
            why=(
                f"{kind} of body {body} can collide with {len(others)} {other_kind} geom(s) ({shown}{more}), "
                f"and MJX has no {'-'.join(t.lower() for t in types)} collision: its put_model refuses the "
                "model"
            ),
            fix=(
                f"make {name} {shape} of the same size, or keep the pairs apart: contype/conaffinity "
                "without a common bit, or <contact><exclude body1=... body2=.../></contact> in the MJCF"
            ),
            location=target.element_location(("geom",), name),
        )


def _hull_vertices(model: mujoco.MjModel, mesh: int) -> int:
    """Vertices of the mesh's convex hull (what MJX collides), or of the mesh when it has none."""
    address = int(model.mesh_graphadr[mesh])
    return int(model.mesh_graph[address]) if address >= 0 else int(model.mesh_vertnum[mesh])


def mjx_mesh_margins_and_sizes(target: LintTarget) -> Iterator[Finding]:
    """RA814 (error): margin or gap on a mesh or heightfield pair; RA815 (warning): a hull too big for MJX."""
    model = target.model
    limits: dict[int, int] = {}  # mesh geom -> the smallest hull it should have, over its pairs
    for first, second, pair in collidable_pairs(model):
        types = {int(model.geom_type[first]), int(model.geom_type[second])}
        margin = (
            model.pair_margin[pair] if pair >= 0 else model.geom_margin[first] + model.geom_margin[second]
        )
        if types & {MESH, HFIELD} and margin:
            subject, described = _pair_subject(target, first, second)
            yield Finding(
                code="RA814",
                severity="error",
                subject=subject,
                why=f"{described} have margin {margin:g}: MJX's put_model refuses margin/gap on meshes and "
                "heightfields (NotImplementedError)",
                fix='set margin="0" (and gap="0") on these geoms (or their <pair>)',
                location=target.element_location(("geom",), target.element_name(GEOM, second)),
            )
        limit = HULL_VERTICES_WITH_MESHES if types == {MESH} else HULL_VERTICES_WITH_PRIMITIVES
        for geom in (first, second):
            if int(model.geom_type[geom]) == MESH:
                limits[geom] = min(limits.get(geom, limit), limit)
    for geom, limit in sorted(limits.items()):
        mesh = int(model.geom_dataid[geom])
        vertices = _hull_vertices(model, mesh)
        if vertices < limit or (limit == HULL_VERTICES_WITH_PRIMITIVES and vertices == limit):
            continue
        mesh_name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_MESH, mesh) or f"mesh #{mesh}"
        against = "another mesh" if limit == HULL_VERTICES_WITH_MESHES else "primitives"
        name = target.element_name(GEOM, geom)
        part = target.part_of(mesh_name)
        local = mesh_name[len(part.naming_prefix) :] if part else mesh_name
        suggested = HULL_VERTICES_WITH_MESHES - 1 if limit == HULL_VERTICES_WITH_MESHES else 64
        yield Finding(
            code="RA815",
            severity="warning",
            subject=name,
            why=(
                f"mesh {mesh_name}'s convex hull has {vertices} vertices and collides with {against}: MJX's "
                f"separating-axis test grows with the hull (its documentation asks for "
                f"{'fewer than 32' if limit == HULL_VERTICES_WITH_MESHES else 'about 200 or less'})"
            ),
            fix=f'add maxhullvert="{suggested}" to <mesh name="{local}"> in the MJCF, or collide with a '
            "simpler geom",
            location=target.element_location(("geom",), name),
        )
