"""What changed between two compiled models: elements added and removed, and the values reviewers
ask about (joint ranges and dynamics, body masses, actuator ranges and gains, the home pose).

Elements are matched by name, so both models must be built with the same instance number.
Values are read from the compiled ``MjModel`` (after defaults, classes and joint rules), which is
what a simulation uses; numbers equal to within 1e-9 relative are the same.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np

from assembler.compiler.keyframe import HOME_KEY

Value = float | list[float] | None
Properties = dict[str, dict[str, Value]]
"""Element name -> property name -> value."""

ELEMENTS: tuple[str, ...] = ("body", "joint", "actuator")
"""The element kinds compared, in report order."""


@dataclass(frozen=True)
class ModelChange:
    """One property of one element whose value differs between the two models."""

    element: str
    name: str
    property: str
    before: Value
    after: Value


@dataclass(frozen=True)
class ModelDiff:
    """Elements only in the second model (added), only in the first (removed), and changed values."""

    added: dict[str, list[str]] = field(default_factory=dict)
    removed: dict[str, list[str]] = field(default_factory=dict)
    changed: list[ModelChange] = field(default_factory=list)

    @property
    def empty(self) -> bool:
        """True when the models agree on everything compared."""
        return not (any(self.added.values()) or any(self.removed.values()) or self.changed)


def _value(array: Any) -> Value:
    values = [float(x) for x in np.atleast_1d(array)]
    return values[0] if len(values) == 1 else values


def _home_qpos(model: mujoco.MjModel) -> np.ndarray[Any, Any]:
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    return np.asarray(model.key_qpos[key] if key >= 0 else model.qpos0)


QPOS_WIDTH = {mujoco.mjtJoint.mjJNT_FREE: 7, mujoco.mjtJoint.mjJNT_BALL: 4}
DOF_WIDTH = {mujoco.mjtJoint.mjJNT_FREE: 6, mujoco.mjtJoint.mjJNT_BALL: 3}
"""Widths of free and ball joints; slide and hinge joints have one of each."""


def _named(model: mujoco.MjModel, kind: str, count: int, start: int = 0) -> list[tuple[int, str]]:
    """(id, name) of the named elements of one kind; unnamed ones cannot be matched across models."""
    accessor = getattr(model, kind)
    return [(i, accessor(i).name) for i in range(start, count) if accessor(i).name]


def bodies(model: mujoco.MjModel) -> Properties:
    """Named bodies (the world excepted) and their masses."""
    return {name: {"mass": float(model.body_mass[i])} for i, name in _named(model, "body", model.nbody, 1)}


def joints(model: mujoco.MjModel) -> Properties:
    """Named joints: range (None when unlimited), damping, armature, frictionloss, stiffness, home qpos."""
    home = _home_qpos(model)
    found: Properties = {}
    for j, name in _named(model, "joint", model.njnt):
        kind = mujoco.mjtJoint(model.jnt_type[j])
        dof = slice(model.jnt_dofadr[j], model.jnt_dofadr[j] + DOF_WIDTH.get(kind, 1))
        qpos = slice(model.jnt_qposadr[j], model.jnt_qposadr[j] + QPOS_WIDTH.get(kind, 1))
        found[name] = {
            "range": _value(model.jnt_range[j]) if model.jnt_limited[j] else None,
            "damping": _value(model.dof_damping[dof]),
            "armature": _value(model.dof_armature[dof]),
            "frictionloss": _value(model.dof_frictionloss[dof]),
            "stiffness": _value(model.jnt_stiffness[j]),
            "home qpos": _value(home[qpos]),
        }
    return found


def actuators(model: mujoco.MjModel) -> Properties:
    """Named actuators: ctrlrange and forcerange (None when unlimited), gain and bias parameters."""
    return {
        name: {
            "ctrlrange": _value(model.actuator_ctrlrange[a]) if model.actuator_ctrllimited[a] else None,
            "forcerange": _value(model.actuator_forcerange[a]) if model.actuator_forcelimited[a] else None,
            "gainprm": _value(model.actuator_gainprm[a, :3]),  # kp for position actuators
            "biasprm": _value(model.actuator_biasprm[a, :3]),  # (0, -kp, -kv) for position actuators
        }
        for a, name in _named(model, "actuator", model.nu)
    }


READERS = {"body": bodies, "joint": joints, "actuator": actuators}


def same(before: Value, after: Value) -> bool:
    """Equal, numbers to within 1e-9 relative (or 1e-12 absolute)."""
    if before is None or after is None:
        return before is after
    a, b = np.atleast_1d(before), np.atleast_1d(after)
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=1e-9, atol=1e-12))


def model_changes(before: mujoco.MjModel, after: mujoco.MjModel) -> ModelDiff:
    """Elements added and removed, and every compared property that differs, element kind by kind."""
    diff = ModelDiff()
    for element in ELEMENTS:
        old, new = READERS[element](before), READERS[element](after)
        diff.added[element] = [name for name in new if name not in old]
        diff.removed[element] = [name for name in old if name not in new]
        for name in (n for n in old if n in new):
            for prop, value in old[name].items():
                if not same(value, new[name][prop]):
                    diff.changed.append(ModelChange(element, name, prop, value, new[name][prop]))
    return diff
