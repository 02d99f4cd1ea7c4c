"""RA201-RA203: masses and inertias that no real object of the body's shape could have.

MuJoCo takes an ``<inertial>`` as written. Placeholder values (1 kg, 0.1 kg m^2 everywhere), a
mass in grams or an inertia in g cm^2 compile and simulate, but wrongly. The checks judge each
moving rigid piece (bodies welded together count as one, as MuJoCo simulates them) against the
volume and reach of its geoms.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco
import numpy as np

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.tools.lint.geometry import FloatArray, reach, shape_volume

DENSITY_RANGE = (100.0, 20000.0)
"""Plausible mean densities (kg/m^3): from foam and hollow plastic shells to tungsten."""

MIN_VOLUME = 1e-6
"""Pieces whose geoms enclose less than 1 cm^3 are markers, not shapes: their density is not judged."""

MIN_MASS = 1e-6
"""Bodies lighter than 1 mg are placeholders (MuJoCo wants a mass on every moving body): not judged."""

MIN_GYRATION = 1e-4
"""A radius of gyration (m) below 0.1 mm about some axis: no real link is that thin (a 1 mm wire is not)."""

REACH_FACTOR = 1.5
"""Slack on the radius of gyration: geoms approximate a link, so its mass may sit a little beyond them."""

BODY = mujoco.mjtObj.mjOBJ_BODY


def _rigid_pieces(model: mujoco.MjModel) -> dict[int, list[int]]:
    """Moving rigid pieces: the first body of each group welded together -> the group's bodies."""
    pieces: dict[int, list[int]] = {}
    for body in range(1, model.nbody):
        weld = int(model.body_weldid[body])
        if weld != 0:  # bodies welded to the world never move: their masses do not matter
            pieces.setdefault(weld, []).append(body)
    return pieces


def _geoms_of(model: mujoco.MjModel, bodies: list[int]) -> list[int]:
    return [g for g in range(model.ngeom) if int(model.geom_bodyid[g]) in bodies]


def implausible_density(target: LintTarget) -> Iterator[Finding]:
    """RA201 (warning): a rigid piece's mass over its geoms' volume is outside 100..20000 kg/m^3."""
    model = target.model
    low, high = DENSITY_RANGE
    for root, bodies in _rigid_pieces(model).items():
        volume = shape_volume(model, _geoms_of(model, bodies))
        if volume < MIN_VOLUME:
            continue
        mass = float(sum(model.body_mass[b] for b in bodies))
        density = mass / volume
        if low <= density <= high:
            continue
        name = target.element_name(BODY, root)
        welded = f" (with {len(bodies) - 1} welded child bodies)" if len(bodies) > 1 else ""
        yield Finding(
            code="RA201",
            severity="warning",
            subject=name,
            why=(
                f"mass {mass:.4g} kg in {volume * 1e6:.4g} cm^3 of geoms{welded} is a density of "
                f"{density:.4g} kg/m^3, outside {low:g}..{high:g}"
            ),
            fix="check the <inertial> mass (kg, not g) and the geom sizes (m); replace a placeholder mass",
            location=target.element_location(("body",), name),
        )


def piece_inertia(model: mujoco.MjModel, data: mujoco.MjData, bodies: list[int]) -> tuple[float, FloatArray]:
    """Total mass and principal moments (about the common centre of mass) of bodies welded together."""
    masses = model.body_mass[bodies]
    mass = float(masses.sum())
    if mass <= 0:
        return 0.0, np.zeros(3)
    centre = (masses[:, None] * data.xipos[bodies]).sum(axis=0) / mass
    total = np.zeros((3, 3))
    for body in bodies:
        rotation = data.ximat[body].reshape(3, 3)
        offset = data.xipos[body] - centre
        total += rotation @ np.diag(model.body_inertia[body]) @ rotation.T
        total += model.body_mass[body] * (offset @ offset * np.eye(3) - np.outer(offset, offset))
    return mass, np.linalg.eigvalsh(total)


def degenerate_inertia(target: LintTarget) -> Iterator[Finding]:
    """RA202 (error): a piece that can hardly rotate about some axis, or an inertia MuJoCo rebalanced."""
    model, data = target.model, target.data
    for root, bodies in _rigid_pieces(model).items():
        mass, moments = piece_inertia(model, data, bodies)
        if mass < MIN_MASS or moments.min() >= mass * MIN_GYRATION**2:
            continue
        name = target.element_name(BODY, root)
        yield Finding(
            code="RA202",
            severity="error",
            subject=name,
            why=(
                f"mass {mass:.4g} kg with principal moments {np.array2string(moments, precision=3)} "
                f"kg m^2: a radius of gyration under {MIN_GYRATION * 1000:g} mm, as if it had no extent "
                "along one axis"
            ),
            fix="give the <inertial> the link's diaginertia or fullinertia (kg m^2, about its mass centre)",
            location=target.element_location(("body",), name),
        )
    for part in target.parts:
        for body in part.source.pristine.bodies[1:]:
            authored = _authored_moments(body)
            if authored is None or authored.sum() <= 0:
                continue
            if 2 * authored.max() <= authored.sum() * (1 + 1e-6):
                continue
            name = part.naming_prefix + body.name
            yield Finding(
                code="RA202",
                severity="error",
                subject=name,
                why=(
                    f"authored principal moments {np.array2string(authored, precision=4)} kg m^2 violate "
                    "A + B >= C (no physical body has them); MuJoCo's balanceinertia replaced them silently"
                ),
                fix="correct the <inertial> (often a typo or a wrong unit in one component)",
                location=target.element_location(("body",), name),
            )


def _authored_moments(body: mujoco.MjsBody) -> FloatArray | None:
    """Principal moments of an explicit ``<inertial>`` as written, or None without one."""
    if not body.explicitinertial:
        return None
    full = np.asarray(body.fullinertia, dtype=float)
    if np.isnan(full[0]):
        return np.asarray(body.inertia, dtype=float)
    xx, yy, zz, xy, xz, yz = full
    return np.linalg.eigvalsh(np.array([[xx, xy, xz], [xy, yy, yz], [xz, yz, zz]]))


def oversized_inertia(target: LintTarget) -> Iterator[Finding]:
    """RA203 (warning): a radius of gyration larger than the body's geoms reach from its centre of mass."""
    model, data = target.model, target.data
    for bodies in _rigid_pieces(model).values():
        for body in bodies:
            mass = float(model.body_mass[body])
            extent = reach(data, model, data.xipos[body], _geoms_of(model, bodies))
            if mass < MIN_MASS or extent <= 0:
                continue
            gyration = float(np.sqrt(model.body_inertia[body].max() / mass))
            if gyration <= REACH_FACTOR * extent:
                continue
            name = target.element_name(BODY, body)
            yield Finding(
                code="RA203",
                severity="warning",
                subject=name,
                why=(
                    f"inertia {model.body_inertia[body].max():.4g} kg m^2 for {mass:.4g} kg is a radius of "
                    f"gyration of {gyration:.3g} m, but the geoms reach only {extent:.3g} m from its centre "
                    "of mass"
                ),
                fix="use the link's real inertia (CAD or identification) in <inertial>, not a placeholder",
                location=target.element_location(("body",), name),
            )
