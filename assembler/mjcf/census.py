"""Counts and facts about a model's elements: how many of each kind (none lost), how many ``size``
numbers a type reads, and which bodies' mass depends on the counted groups.

How many elements of each kind a spec or a compiled model holds, and the check that none is lost.

MjSpec's ``attach`` drops what it cannot resolve without a word, so the assembler counts: after a
build, the assembly holds at least the elements of its parts (each base type says what it
contributes: ``RobotBaseModel.census_contribution``), and a compiled model holds
as many as the spec it was compiled from. A shortfall is a bug in the assembler, not a user's
mistake (every file is first checked as MuJoCo checks it: :mod:`assembler.mjcf.xml_guard`), so it
raises :class:`ElementsLost`, which the CLI does not catch: it crashes loudly with a traceback.

Keyframes are not counted: every part's keyframes are replaced by the assembly's one ``home``.

How many of a geom's or site's three ``size`` numbers its type reads.

A sphere reads its radius, a capsule or cylinder its radius and half-length, a box or ellipsoid all
three. MuJoCo's XML writer writes only those, so a value in the others does not survive
``get_xml()`` (a reload takes the default there): a body's ``size_scale`` scales the numbers a type
reads and leaves the rest, and the model compiled and the model reloaded from its XML agree.

Bodies whose mass depends on which geom groups count: MuJoCo infers a body's inertia from its
geoms when it has no ``<inertial>``, counting only geoms whose group is in the compiler's
``inertiagrouprange`` (MuJoCo's default: 0 to 5, every group). robosuite's world sets it to
``0 0``: there such a body weighs only its collision (group 0) geoms, not its visual ones, and the
model robosuite simulates differs from the one ``assembler build`` writes.
"""

from __future__ import annotations

import math
from collections import Counter
from collections.abc import Mapping

import mujoco
import numpy as np
from numpy.typing import NDArray

KINDS: dict[str, str] = {
    "bodies": "nbody",
    "joints": "njnt",
    "geoms": "ngeom",
    "sites": "nsite",
    "actuators": "nu",
    "sensors": "nsensor",
    "tendons": "ntendon",
    "equalities": "neq",
    "pairs": "npair",
    "excludes": "nexclude",
    "cameras": "ncam",
    "lights": "nlight",
    "materials": "nmat",
    "meshes": "nmesh",
    "textures": "ntex",
    "hfields": "nhfield",
    "skins": "nskin",
    "flexes": "nflex",
    "numerics": "nnumeric",
    "texts": "ntext",
    "tuples": "ntuple",
}
"""Each counted kind: its list on ``MjSpec`` -> its size on ``MjModel``."""

DISCARDED_BY: dict[str, tuple[str, ...]] = {
    "discardvisual": ("geoms", "meshes", "materials", "textures"),
    "fusestatic": ("bodies",),
}
"""Compiler options with which MuJoCo's compile itself leaves elements of these kinds out."""

Census = Counter[str]
"""Kind -> number of elements."""


class ElementsLost(RuntimeError):
    """An assembly lost elements of its parts: a bug in the assembler (never a user's mistake)."""

    def __init__(self, what: str, shortfall: Mapping[str, tuple[int, int]]) -> None:
        details = ", ".join(f"{kind}: {have} of {want}" for kind, (have, want) in shortfall.items())
        super().__init__(
            f"internal error, a bug in robot-assembler (please report it with the spec): {what} "
            f"lost elements of its parts ({details})"
        )


def of_spec(spec: mujoco.MjSpec) -> Census:
    """The elements of ``spec`` per kind (the world body not counted)."""
    census = Counter({kind: len(getattr(spec, kind)) for kind in KINDS})
    census["bodies"] -= 1
    return census


def of_model(model: mujoco.MjModel) -> Census:
    """The elements of a compiled model per kind (the world body not counted)."""
    census = Counter({kind: int(getattr(model, size)) for kind, size in KINDS.items()})
    census["bodies"] -= 1
    return census


def require_at_least(have: Census, want: Census, what: str, exempt: frozenset[str] = frozenset()) -> None:
    """Raise :class:`ElementsLost` when ``have`` holds fewer elements of some kind than ``want``."""
    shortfall = {
        kind: (have[kind], want[kind]) for kind in KINDS if kind not in exempt and have[kind] < want[kind]
    }
    if shortfall:
        raise ElementsLost(what, shortfall)


def require_growth(assembly: mujoco.MjSpec, before: Census, want: Census, what: str) -> None:
    """Raise :class:`ElementsLost` when ``assembly`` grew by fewer elements of some kind than
    ``want`` since it held ``before``."""
    grown = of_spec(assembly)
    grown.subtract(before)
    require_at_least(grown, want, what)


def check_compiled(spec: mujoco.MjSpec, model: mujoco.MjModel, what: str) -> None:
    """The compiled ``model`` holds every element of ``spec``, except those MuJoCo discards on the
    spec's own request (``discardvisual``, ``fusestatic``)."""
    exempt = frozenset(
        kind for option, kinds in DISCARDED_BY.items() if getattr(spec.compiler, option) for kind in kinds
    )
    require_at_least(of_model(model), of_spec(spec), f"compiling {what}", exempt)


READ_SIZES: dict[int, int] = {
    int(mujoco.mjtGeom.mjGEOM_SPHERE): 1,
    int(mujoco.mjtGeom.mjGEOM_CAPSULE): 2,
    int(mujoco.mjtGeom.mjGEOM_CYLINDER): 2,
    int(mujoco.mjtGeom.mjGEOM_ELLIPSOID): 3,
    int(mujoco.mjtGeom.mjGEOM_BOX): 3,
}
"""Primitive type -> the sizes it reads; every other type (plane, mesh, height field) keeps all three."""


def scaled_size(size: NDArray[np.float64], kind: int, factor: float) -> NDArray[np.float64]:
    """``size`` with the numbers a geom or site of type ``kind`` reads multiplied by ``factor``."""
    scaled = np.array(size, dtype=float)
    scaled[: READ_SIZES.get(int(kind), 3)] *= factor
    return scaled


def _weighs(geom: mujoco.MjsGeom) -> bool:
    return bool(geom.mass > 0 if not math.isnan(geom.mass) else geom.density > 0)


def weighed_by_other_groups(mjspec: mujoco.MjSpec, groups: tuple[int, int]) -> list[str]:
    """The bodies of ``mjspec`` (names, in document order) without an explicit inertial that have a
    massive geom outside ``groups``: their inferred mass changes when only ``groups`` count."""
    low, high = groups
    return [
        body.name
        for body in mjspec.bodies
        if body.name != "world"
        and not body.explicitinertial
        and any(_weighs(geom) and not low <= geom.group <= high for geom in body.geoms)
    ]
