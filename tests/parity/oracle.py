"""Compare our compiled model with robosuite's, element by element and field by field.

Every difference is one line, ``{family} {key}: {what}``, where family is one of ``FAMILIES`` plus
``order``, ``contact``, ``keyframe`` and ``option``. Numbers agree within a relative tolerance of
1e-6. Elements pair by key (keys.py); an element on one side only is one line.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import Any

import mujoco
import numpy as np

from tests.parity.fields import FAMILIES
from tests.parity.keys import KINDS, Keys, model_keys
from tests.parity.robosuite_side import Reference

TOLERANCE = 1e-6
"""Relative tolerance of every numeric comparison (the parity issue's figure), relative to the larger
magnitude in the compared array: a rotated vector's near-zero component is not held to 1e-6 of
itself. (robosuite's ``set_base_ori`` rounds its quaternion to float32 in ``mat2quat``: ~1e-7.)"""

HOME = "home"


def _close(a: Any, b: Any) -> bool:
    a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
    if a.shape != b.shape:
        return False
    if np.array_equal(a, b):  # most fields: fast
        return True
    finite = np.isfinite(a)
    if not np.array_equal(finite, np.isfinite(b)) or not np.array_equal(a[~finite], b[~finite]):
        return False
    scale = max(np.abs(a[finite]).max(initial=0.0), np.abs(b[finite]).max(initial=0.0))
    return bool(np.all(np.abs(a[finite] - b[finite]) <= TOLERANCE * scale + TOLERANCE * 1e-3))


def _same(a: Any, b: Any) -> bool:
    if isinstance(a, str) or isinstance(b, str):
        return a == b
    return _close(a, b)


def show(value: Any) -> str:
    """A value as a short readable text (long arrays elided)."""
    if isinstance(value, str):
        return value
    array = np.asarray(value)
    if array.ndim == 0:
        return f"{array.item():.9g}"
    return np.array2string(array.ravel(), precision=6, threshold=12, separator=" ", max_line_width=10**6)


class _Side:
    """One compiled model with its kinematics at qpos0 and the keys of its elements."""

    def __init__(self, model: mujoco.MjModel, keys: Keys) -> None:
        self.model, self.keys = model, keys
        self.data = mujoco.MjData(model)
        mujoco.mj_kinematics(model, self.data)
        mujoco.mj_comPos(model, self.data)
        mujoco.mj_camlight(model, self.data)

    def index(self, kind: str) -> dict[str, int]:
        """Key -> index of every element of ``kind`` (bodies: every body the other side has)."""
        if kind == "body":
            return {key: i for i, key in enumerate(self.keys.body) if key is not None and i > 0}
        return {key: i for i, key in enumerate(self.keys.kinds[kind])}


def differences(
    ours: mujoco.MjModel, reference: Reference, renamed: Mapping[str, str | None] | None = None
) -> list[str]:
    """Every way ``ours`` differs from robosuite's ``reference``, one line each (empty: identical).

    ``renamed`` maps our body names to robosuite's for bodies we name differently on purpose, or to
    None for a body robosuite does not have (its children, geoms, sites... then count as its
    parent's). Each entry that applies is reported as one line; the rest is compared as usual.
    """
    found: list[str] = []
    body_names = {mujoco.mj_id2name(ours, mujoco.mjtObj.mjOBJ_BODY, i) for i in range(ours.nbody)}
    renames, extra = {}, set()
    for name, other in (renamed or {}).items():
        if name not in body_names:
            continue
        if other is None:
            extra.add(name)
            found.append(f"body {name}: not in robosuite")
            if (mass := ours.body(name).mass[0]) != 0:  # its geoms and children pair with its parent's
                found.append(f"body {name}: mass {show(mass)}, which robosuite does not have")
        else:
            renames[name] = other
            found.append(f"body {name}: named {other} in robosuite")
    a = _Side(ours, model_keys(ours, renames, frozenset(extra)))
    b = _Side(reference.model, model_keys(reference.model))
    for family, extract in FAMILIES.items():
        found += _paired(family, a, b, lambda side, i, f=extract: f(side.model, side.data, side.keys, i))
    found += _order(a, b, "joint") + _order(a, b, "actuator")
    found += _contacts(a, b) + _keyframes(a, b, reference) + _options(ours.opt, reference.model.opt)
    return found


def _paired(family: str, a: _Side, b: _Side, fields: Any) -> list[str]:
    ours, theirs = a.index(family), b.index(family)
    found = [f"{family} {key}: only ours" for key in ours if key not in theirs]
    found += [f"{family} {key}: only robosuite" for key in theirs if key not in ours]
    for key in (k for k in ours if k in theirs):
        mine, other = fields(a, ours[key]), fields(b, theirs[key])
        for name, value in mine.items():
            if not _same(value, other[name]):
                found.append(f"{family} {key}: {name} {show(value)} != {show(other[name])}")
    return found


def _order(a: _Side, b: _Side, kind: str) -> list[str]:
    """The common elements of ``kind`` in the same order (joints: qpos layout; actuators: ctrl)."""
    ours, theirs = a.keys.kinds[kind], b.keys.kinds[kind]
    common = set(ours) & set(theirs)
    mine, other = [k for k in ours if k in common], [k for k in theirs if k in common]
    for position, (x, y) in enumerate(zip(mine, other, strict=True)):
        if x != y:
            return [f"order {kind}s: {x} != {y} at position {position}"]
    return []


def _contacts(a: _Side, b: _Side) -> list[str]:
    """Contact pairs (by their two geoms) field by field, and excluded body pairs."""

    def pairs(side: _Side) -> dict[str, dict[str, Any]]:
        model, geoms = side.model, side.keys.kinds["geom"]
        return {
            f"{geoms[model.pair_geom1[p]]} + {geoms[model.pair_geom2[p]]}": {
                "condim": model.pair_dim[p],
                "friction": model.pair_friction[p],
                "solref": model.pair_solref[p],
                "friction solref": model.pair_solreffriction[p],
                "solimp": model.pair_solimp[p],
                "margin": model.pair_margin[p],
                "gap": model.pair_gap[p],
            }
            for p in range(model.npair)
        }

    def excludes(side: _Side) -> set[str]:
        signatures = side.model.exclude_signature
        return {f"{side.keys.body_key(s >> 16)} + {side.keys.body_key(s & 0xFFFF)}" for s in signatures}

    ours, theirs = pairs(a), pairs(b)
    found = [f"contact pair {k}: only ours" for k in ours if k not in theirs]
    found += [f"contact pair {k}: only robosuite" for k in theirs if k not in ours]
    for key in (k for k in ours if k in theirs):
        found += [
            f"contact pair {key}: {name} {show(v)} != {show(theirs[key][name])}"
            for name, v in ours[key].items()
            if not _same(v, theirs[key][name])
        ]
    mine, other = excludes(a), excludes(b)
    found += [f"contact exclude {k}: only ours" for k in sorted(mine - other)]
    found += [f"contact exclude {k}: only robosuite" for k in sorted(other - mine)]
    return found


def _keyframes(a: _Side, b: _Side, reference: Reference) -> list[str]:
    """Our ``home`` keyframe against robosuite's reset pose, joint by joint and actuator by actuator;
    any other keyframe against robosuite's keyframe of the same name."""

    def by_key(side: _Side, qpos: np.ndarray, ctrl: np.ndarray) -> dict[str, Any]:
        model, values = side.model, {}
        for j, key in enumerate(side.keys.kinds["joint"]):
            start = model.jnt_qposadr[j]
            end = model.jnt_qposadr[j + 1] if j + 1 < model.njnt else model.nq
            values[f"qpos of joint {key}"] = qpos[start:end]
        for u, key in enumerate(side.keys.kinds["actuator"]):
            values[f"ctrl of actuator {key}"] = ctrl[u]
        return values

    keyframes = {HOME: (reference.home_qpos, reference.home_ctrl)}
    for k, name in enumerate(b.keys.kinds["key"]):
        keyframes[name] = (b.model.key_qpos[k], b.model.key_ctrl[k])
    ours = {name: k for k, name in enumerate(a.keys.kinds["key"])}
    found = [f"keyframe {name}: only ours" for name in ours if name not in keyframes]
    found += [f"keyframe {name}: only robosuite" for name in keyframes if name not in ours]
    for name, (qpos, ctrl) in keyframes.items():
        if name not in ours:
            continue
        mine = by_key(a, a.model.key_qpos[ours[name]], a.model.key_ctrl[ours[name]])
        other = by_key(b, qpos, ctrl)
        found += [
            f"keyframe {name}: {what} {show(v)} != {show(other[what])}"
            for what, v in mine.items()
            if what in other and not _same(v, other[what])
        ]
    return found


def _options(ours: Any, theirs: Any) -> list[str]:
    """Every field of ``<option>`` (MjOption)."""
    names = [n for n in dir(ours) if not n.startswith("_") and not callable(getattr(ours, n))]
    return [
        f"option {n}: {show(getattr(ours, n))} != {show(getattr(theirs, n))}"
        for n in names
        if not _same(getattr(ours, n), getattr(theirs, n))
    ]


def families(lines: Iterable[str]) -> set[str]:
    """The families of difference lines (``joint``, ``geom``, ``order``, ``contact`` ...)."""
    return {line.split(" ", 1)[0].rstrip(":") for line in lines}


__all__ = ["KINDS", "TOLERANCE", "differences", "families", "show"]
