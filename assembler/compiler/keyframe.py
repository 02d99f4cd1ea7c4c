"""Compile an assembly with one ``home`` keyframe: every part's initial pose, actuators holding it.

MjSpec never merges keyframes of attached parts (MuJoCo issue #2102), so the assembler owns the
keyframe: it is added empty (MuJoCo fills it with qpos0), the model is compiled once, the given
joint positions are written at their qpos addresses, and position-like actuators get the
control that holds them there. The result is written back to the spec so emitted XML carries it.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import MjcfError
from assembler.mjcf import census, installed_mujoco

HOME_KEY = "home"

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class Keyframe:
    """The ``home`` keyframe of a compiled model: joint positions and the controls that hold them."""

    qpos: tuple[float, ...]
    ctrl: tuple[float, ...]

    @classmethod
    def of(cls, model: mujoco.MjModel) -> Keyframe:
        """The model's ``home`` keyframe."""
        index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
        return cls(tuple(model.key_qpos[index].tolist()), tuple(model.key_ctrl[index].tolist()))

    def write(self, mjspec: mujoco.MjSpec) -> None:
        """Give ``mjspec`` this ``home`` keyframe (replacing one it has), so its XML carries it."""
        key = _home_key(mjspec)
        key.qpos = list(self.qpos)
        key.ctrl = list(self.ctrl)


def _home_key(spec: mujoco.MjSpec) -> mujoco.MjsKey:
    for key in spec.keys:
        if key.name == HOME_KEY:
            key.qpos = []
            key.ctrl = []
            return key
    key = spec.add_key()
    key.name = HOME_KEY
    return key


def _holds_position(model: mujoco.MjModel, actuator: int) -> bool:
    """True for an actuator whose force is kp * (ctrl - qpos), i.e. ctrl is a joint position target."""
    on_joint = model.actuator_trntype[actuator] == mujoco.mjtTrn.mjTRN_JOINT
    kp = model.actuator_gainprm[actuator, 0]
    return bool(on_joint and kp > 0 and np.isclose(model.actuator_biasprm[actuator, 1], -kp))


def home_control(model: mujoco.MjModel, qpos: FloatArray) -> FloatArray:
    """Controls that hold ``qpos``: position targets for position actuators, zero for the rest."""
    ctrl = np.zeros(model.nu)
    for actuator in range(model.nu):
        if _holds_position(model, actuator):
            joint = model.actuator_trnid[actuator, 0]
            ctrl[actuator] = qpos[model.jnt_qposadr[joint]]
            if model.actuator_ctrllimited[actuator]:
                low, high = model.actuator_ctrlrange[actuator]
                ctrl[actuator] = np.clip(ctrl[actuator], low, high)
    return ctrl


Compiler = Callable[[mujoco.MjSpec], mujoco.MjModel]
"""How a spec is compiled: MuJoCo's own compile, or one reading stored meshes (assembler.cache)."""


def compile_spec(spec: mujoco.MjSpec) -> mujoco.MjModel:
    """MuJoCo's compile of ``spec``, reading every file."""
    return spec.compile()


def compile_with_home(
    spec: mujoco.MjSpec, home: Mapping[str, float], what: str, compile: Compiler = compile_spec
) -> mujoco.MjModel:
    """Compile ``spec`` (with ``compile``) with a ``home`` keyframe at the given joint positions
    (others at qpos0)."""
    key = _home_key(spec)
    try:
        with installed_mujoco.warned(what):
            model = compile(spec)
    except ValueError as error:
        message = " ".join(str(error).split()).removeprefix("Error: ")
        raise MjcfError(f"{what}: MuJoCo cannot compile the assembly: {message}") from None
    census.check_compiled(spec, model, what)
    index = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    qpos = model.qpos0.copy()
    for name, value in home.items():
        qpos[model.jnt_qposadr[model.joint(name).id]] = value
    ctrl = home_control(model, qpos)
    model.key_qpos[index] = qpos
    model.key_ctrl[index] = ctrl
    key.qpos = qpos.tolist()
    key.ctrl = ctrl.tolist()
    return model
