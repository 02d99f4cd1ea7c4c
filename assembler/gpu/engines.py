"""What the GPU targets' checks share: tables of MuJoCo kinds an engine refuses, and the pairs that collide.

MuJoCo Warp and MJX refuse some models MuJoCo runs (``put_model`` raises ``NotImplementedError``) and
run others badly. The checks read the compiled ``MjModel`` only, never import either engine, so
``assembler lint --target mjwarp`` works where neither is installed. Kinds are named as MuJoCo's
enums name them (``mjSOL_PGS``), so a name that a MuJoCo version lacks is simply never present;
tests/tools/test_gpu_lint.py compares these tables with each engine's own where it is installed.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

import mujoco

from assembler.checks.finding import Finding, Severity
from assembler.checks.target import ACTUATOR_TAGS, LintTarget
from assembler.errors import Location
from assembler.files.paths import display_path

Engine = Literal["mujoco", "mjwarp", "mjx"]
"""What ``assembler lint --target`` checks a model for: MuJoCo alone, or also MuJoCo Warp or MJX."""

ENGINES: tuple[Engine, ...] = ("mujoco", "mjwarp", "mjx")

ENGINE_NAMES: dict[Engine, str] = {"mujoco": "MuJoCo", "mjwarp": "MuJoCo Warp", "mjx": "MJX"}


@dataclass(frozen=True)
class KindTable:
    """Values of one model field (e.g. ``actuator_dyntype``) that an engine refuses, by enum member name."""

    field: str
    """The ``MjModel`` array, e.g. ``actuator_dyntype``; its prefix names the element (actuator, eq, ...)."""

    enum: str
    """The MuJoCo enum its values belong to, e.g. ``mjtDyn``."""

    refused: tuple[str, ...]
    """Member names the engine refuses, e.g. ``("mjDYN_PID",)``."""

    def refused_values(self) -> dict[int, str]:
        """Value -> name of the refused members this MuJoCo has."""
        enum = getattr(mujoco, self.enum)
        return {int(getattr(enum, name)): name for name in self.refused if hasattr(enum, name)}


ELEMENT_KINDS: dict[str, tuple[mujoco.mjtObj, str]] = {
    "actuator": (mujoco.mjtObj.mjOBJ_ACTUATOR, "actuator"),
    "eq": (mujoco.mjtObj.mjOBJ_EQUALITY, "equality"),
    "sensor": (mujoco.mjtObj.mjOBJ_SENSOR, "sensor"),
    "geom": (mujoco.mjtObj.mjOBJ_GEOM, "geom"),
    "body": (mujoco.mjtObj.mjOBJ_BODY, "body"),
}
"""Field prefix -> the element it describes and the word a finding uses for it."""


def element_tags(field: str, member: str | None) -> tuple[str, ...]:
    """MJCF tags that can define the element behind ``field`` (e.g. ``jointlimitpos`` for a sensor)."""
    prefix = field.split("_")[0]
    if prefix == "actuator":
        return (*ACTUATOR_TAGS, "plugin")
    if member is not None and prefix in ("sensor", "eq"):
        return (member.split("_", 1)[1].lower(),)
    return (ELEMENT_KINDS[prefix][1],)


def refused_elements(
    target: LintTarget, table: KindTable, code: str, engine: Engine, fix: str
) -> Iterator[Finding]:
    """One error per element whose ``table.field`` value the engine refuses."""
    prefix = table.field.split("_")[0]
    kind, word = ELEMENT_KINDS[prefix]
    values = getattr(target.model, table.field)
    refused = table.refused_values()
    for index, value in enumerate(values):
        member = refused.get(int(value))
        if member is None:
            continue
        name = target.element_name(kind, index)
        yield Finding(
            code=code,
            severity="error",
            subject=name,
            why=(
                f"{word} of kind {member} ({table.field}): {ENGINE_NAMES[engine]}'s put_model refuses "
                "it (NotImplementedError)"
            ),
            fix=fix,
            location=target.element_location(element_tags(table.field, member), name),
        )


def option_location(target: LintTarget) -> Location | None:
    """The first ``<option`` element in the parts' MJCF files (where solver, integrator and flags are set)."""
    for part in target.parts:
        path = Path(part.source.path)
        try:
            text = path.read_text(encoding="utf-8")
        except (OSError, UnicodeDecodeError):
            continue
        match = re.search(r"<option\b", text)
        if match is not None:
            line_start = text.rfind("\n", 0, match.start()) + 1
            line = text.count("\n", 0, match.start()) + 1
            return Location(display_path(str(path)), line, match.start() - line_start + 1)
    return None


def option_finding(
    target: LintTarget, code: str, engine: Engine, setting: str, fix: str, severity: Severity = "error"
) -> Finding:
    """A finding about ``<option>`` (solver, integrator, flags): put_model refuses the whole model."""
    return Finding(
        code=code,
        severity=severity,
        subject="option",
        why=f"{setting}: {ENGINE_NAMES[engine]}'s put_model refuses it (NotImplementedError)",
        fix=fix,
        location=option_location(target),
    )


def refused_solver_and_enable_flags(
    target: LintTarget, code: str, engine: Engine, solvers: tuple[str, ...], enabled: tuple[str, ...]
) -> Iterator[Finding]:
    """The solver and enable flags of ``<option>`` that ``engine`` refuses (both engines check these
    two alike; each has more of its own)."""
    option = target.model.opt
    solver = mujoco.mjtSolver(int(option.solver)).name
    if solver in solvers:
        yield option_finding(
            target, code, engine, f"solver {solver}", 'set <option solver="Newton"/> (or "CG")'
        )
    for name in flag_names(int(option.enableflags), "mjtEnableBit", enabled):
        flag = name.removeprefix("mjENBL_").lower()
        yield option_finding(
            target, code, engine, f"enable flag {name}", f'remove <flag {flag}="enable"/> from <option>'
        )


def flag_names(flags: int, enum: str, refused: tuple[str, ...]) -> list[str]:
    """The refused members of flag enum ``enum`` (e.g. ``mjtEnableBit``) set in ``flags``."""
    bits = getattr(mujoco, enum)
    return [name for name in refused if hasattr(bits, name) and flags & int(getattr(bits, name))]


def collidable_pairs(model: mujoco.MjModel) -> Iterator[tuple[int, int, int]]:
    """Geom pairs that can collide, as (geom1, geom2, pair index or -1), geom1's type <= geom2's.

    MuJoCo's filter as the GPU engines apply it: explicit ``<pair>`` elements, then geoms of two
    bodies that are not welded together, not parent and child (unless ``filterparent`` is disabled,
    never for the world), not excluded by ``<exclude>``, and whose contype and conaffinity share a
    bit; plane-plane and plane-heightfield pairs are never tested.
    """
    seen: set[tuple[int, int]] = set()
    for index in range(model.npair):
        first, second = int(model.pair_geom1[index]), int(model.pair_geom2[index])
        if model.geom_type[first] > model.geom_type[second]:
            first, second = second, first
        seen.add((first, second))
        yield first, second, index
    excluded = {int(signature) for signature in model.exclude_signature}
    filter_parent = not model.opt.disableflags & mujoco.mjtDisableBit.mjDSBL_FILTERPARENT
    plane, hfield = int(mujoco.mjtGeom.mjGEOM_PLANE), int(mujoco.mjtGeom.mjGEOM_HFIELD)
    contacting = model.geom_contype | model.geom_conaffinity
    geoms = [
        [g for g in range(adr, adr + num) if contacting[g]]
        for adr, num in zip(model.body_geomadr, model.body_geomnum, strict=True)
    ]
    for body1 in range(model.nbody):
        weld1 = int(model.body_weldid[body1])
        parent1 = int(model.body_weldid[model.body_parentid[weld1]])
        for body2 in range(body1, model.nbody):
            if not geoms[body1] or not geoms[body2] or (body1 << 16) + body2 in excluded:
                continue
            weld2 = int(model.body_weldid[body2])
            parent2 = int(model.body_weldid[model.body_parentid[weld2]])
            if weld1 == weld2:
                continue
            if filter_parent and weld1 and weld2 and (weld1 == parent2 or weld2 == parent1):
                continue
            for g1 in geoms[body1]:
                for g2 in geoms[body2]:
                    first, second = (g1, g2) if model.geom_type[g1] <= model.geom_type[g2] else (g2, g1)
                    types = (int(model.geom_type[first]), int(model.geom_type[second]))
                    if types in ((plane, plane), (plane, hfield)):
                        continue
                    bits = model.geom_contype[first] & model.geom_conaffinity[second]
                    bits |= model.geom_contype[second] & model.geom_conaffinity[first]
                    if bits and (first, second) not in seen:
                        seen.add((first, second))
                        yield first, second, -1


def geom_type_name(model: mujoco.MjModel, geom: int) -> str:
    """``box``, ``cylinder``, ... for geom ``geom``."""
    name: str = mujoco.mjtGeom(int(model.geom_type[geom])).name
    return name.removeprefix("mjGEOM_").lower()
