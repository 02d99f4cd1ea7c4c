"""Which of a robot's geoms collide in mjlab, and how: its spec's ``mjlab.collisions`` and feet shorthand.

- Each ``mjlab.collisions`` entry becomes one mjlab ``CollisionCfg`` over the geoms its patterns match
  (whole names, as the MJCF writes them, without the robot prefix), in the spec's order. mjlab's config
  always writes contype, conaffinity, condim and priority, so those an entry leaves out are given as
  each geom has them before it (the MJCF's, or an earlier entry's): leaving a field out keeps it.
  The geoms are handed to mjlab by exact name (mjlab matches its patterns from the start of a name
  only, and sees the prefixed names), and the other geoms are left alone (``disable_other_geoms``
  false): a spec that wants only some geoms to collide says so in an entry of its own.
- ``mjlab.foot_friction`` and ``foot_condim`` come last, on the feet's collision geoms, with priority 1.
- A pattern that matches no geom is an error at its spec line: a misspelt pattern would otherwise leave
  the robot's contacts as they were without a word.
- A geom without a name (a URDF's) is matched, and named in mjlab's copy, as ``<body>_geom<i>``
  (:func:`~assembler.mjlab.task_parts.unnamed_geom_name`): mjlab selects geoms by name.
"""

from __future__ import annotations

import difflib
import re
from dataclasses import dataclass

import mujoco
from mjlab.utils.spec_config import CollisionCfg

from assembler.errors import AssemblerError, Problem
from assembler.mjlab.task_parts import TaskParts, mjlab_geom_name
from assembler.models import RobotModel
from assembler.spec.fieldpath import FieldPath

STRUCTURAL = ("contype", "conaffinity", "condim", "priority")
"""The fields mjlab's ``CollisionCfg`` writes on every geom it matches."""
TUNING = ("friction", "solref", "solimp", "margin", "gap", "solmix")
"""The fields it writes only where given (None keeps the geom's)."""


@dataclass(frozen=True)
class Collisions:
    """The robot's contact settings as mjlab's configs, and the geoms they need named in mjlab's copy."""

    configs: tuple[CollisionCfg, ...]
    unnamed: tuple[str, ...]
    """The names (``<body>_geom<i>``, prefixed) of unnamed geoms the configs select."""


def _whole_name(name: str) -> str:
    """A pattern mjlab's ``re.match`` takes for ``name`` alone (not also ``name`` followed by more)."""
    return re.escape(name) + "$"


def _geom_names(model: mujoco.MjModel) -> list[str]:
    """Each geom's name in mjlab's copy: its own, or ``<body>_geom<i>``."""
    return [mjlab_geom_name(model, geom) for geom in range(model.ngeom)]


def _no_match(robot: RobotModel, path: FieldPath, pattern: str, shown: list[str], prefix: str) -> Problem:
    close = difflib.get_close_matches(pattern, shown, n=1)
    hint = (
        f"Did you mean '{close[0]}'?"
        if close
        else f"Geoms: {', '.join(shown[:8])}{' ...' if len(shown) > 8 else ''}"
    )
    without = f" without the prefix '{prefix}'" if prefix else ""
    return robot.spec_problem(
        path,
        f"'{pattern}' matches no geom of the robot (whole names, as the MJCF writes them{without}). {hint}",
    )


Settings = dict[str, object]
"""A config's fields by name (``contype``, ``friction``, ...); None or absent keeps the geom's value."""


def _config(
    settings: Settings, matched: list[int], names: list[str], state: dict[str, list[int]]
) -> CollisionCfg:
    """``settings`` as mjlab's config over the ``matched`` geoms; ``state`` (per structural field, per geom)
    becomes what the config leaves the geoms with."""
    exact = [_whole_name(names[g]) for g in matched]
    structural: dict[str, int | dict[str, int]] = {}
    for field in STRUCTURAL:
        given = settings.get(field)
        if isinstance(given, int):  # the schema gives an int or None
            structural[field] = given
            for g in matched:
                state[field][g] = given
        else:  # mjlab writes these on every geom it matches: each keeps its own
            structural[field] = {p: state[field][g] for p, g in zip(exact, matched, strict=True)}
    return CollisionCfg(
        geom_names_expr=tuple(exact),
        contype=structural["contype"],
        conaffinity=structural["conaffinity"],
        condim=structural["condim"],
        priority=structural["priority"],
        **{field: settings.get(field) for field in TUNING},
        disable_other_geoms=False,
    )


def collisions(robot: RobotModel, model: mujoco.MjModel, parts: TaskParts) -> Collisions:
    """mjlab's collision configs for ``robot`` (compiled as ``model``): one per ``mjlab.collisions`` entry,
    then the feet's (``foot_friction``, ``foot_condim``); a pattern matching no geom is an error."""
    options, prefix = robot.spec.mjlab, robot.naming_prefix
    names = _geom_names(model)
    shown = [n.removeprefix(prefix) for n in names]
    state = {field: [int(v) for v in getattr(model, f"geom_{field}")] for field in STRUCTURAL}
    configs: list[CollisionCfg] = []
    selected: set[int] = set()
    problems: list[Problem] = []
    for index, entry in enumerate(options.collisions):
        matched: set[int] = set()
        for place, pattern in enumerate(entry.geoms):
            hits = {g for g, name in enumerate(shown) if re.fullmatch(pattern, name)}
            if not hits:
                path = FieldPath(("mjlab", "collisions", index, "geoms", place))
                problems.append(_no_match(robot, path, pattern, shown, prefix))
            matched |= hits
        if not problems:
            configs.append(_config(entry.model_dump(exclude={"geoms"}), sorted(matched), names, state))
            selected |= matched
    if problems:
        raise AssemblerError(problems)
    feet = [names.index(g) for g in parts.foot_geoms]
    if feet and (options.foot_friction is not None or options.foot_condim is not None):
        friction = None if options.foot_friction is None else (options.foot_friction,)
        feet_settings: Settings = {"condim": options.foot_condim, "priority": 1, "friction": friction}
        configs.append(_config(feet_settings, feet, names, state))
        selected |= set(feet)
    unnamed = tuple(names[g] for g in sorted(selected) if not model.geom(g).name)
    return Collisions(configs=tuple(configs), unnamed=unnamed)
