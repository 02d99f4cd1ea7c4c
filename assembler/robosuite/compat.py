"""robosuite 1.5.2 on a MuJoCo it was not written for: its three statements that newer MuJoCo breaks,
rewritten inside robosuite's own modules, each only where this MuJoCo needs it.

robosuite 1.5.2 (the newest release) declares ``mujoco>=3.3.0`` and runs unchanged on 3.9. Three
statements of it fail on newer MuJoCo (``mujoco/doc/changelog.rst`` in the wheel):

- ``mass-matrix``: ``Controller.update`` calls ``mujoco.mj_fullM(model, mass_matrix, data.qM)``; 3.10
  changed the signature to ``mj_fullM(m, d, dst)`` and 3.11 removed ``MjData.qM``. Every controller
  reads the mass matrix, so every environment step failed.
- ``joint-qpos-address`` and ``joint-qvel-address``: ``MjModel.get_joint_qpos_addr``/``_qvel_addr``
  assert ``joint_type in (mjJNT_HINGE, mjJNT_SLIDE)``; on 4.0 a ``mjtJoint`` member no longer equals a
  numpy integer when the member is on the left, which is how a tuple's membership test compares.

Each patch asks this MuJoCo, not its version number, whether robosuite's statement works (a probe on
a one-joint model), and checks that robosuite still holds the exact statement it replaces; when
robosuite changed, the patch is skipped with one line naming it. The rewrite replaces only that
statement: the method's source is read from robosuite's file, the statement substituted, and the
method compiled again in its own module's namespace at its own line numbers (so tracebacks still
point into robosuite's file). The ``mujoco`` module and everything other libraries see of it are
left alone. ``python -m assembler.robosuite --check`` prints each patch's state.
"""

from __future__ import annotations

import importlib
import inspect
import sys
import textwrap
from collections.abc import Callable
from dataclasses import dataclass
from types import FunctionType

import mujoco
import numpy as np

ONE_JOINT = '<mujoco><worldbody><body><joint type="hinge"/><geom size=".1"/></body></worldbody></mujoco>'
"""The model the probes run robosuite's statements on."""

PATCHED = "assembler_patch"
"""The attribute a rewritten method carries: the name of its patch."""


def robosuites_mass_matrix_call_fails() -> bool:
    """Whether ``mj_fullM(model, dst, data.qM)`` (robosuite's call) fails on this MuJoCo."""
    model = mujoco.MjModel.from_xml_string(ONE_JOINT)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    try:
        mujoco.mj_fullM(model, np.zeros((model.nv, model.nv)), data.qM)
    except (AttributeError, TypeError):
        return True
    return False


def new_mass_matrix_call_works() -> bool:
    """Whether ``mj_fullM(model, data, dst)`` (the replacement) works on this MuJoCo."""
    model = mujoco.MjModel.from_xml_string(ONE_JOINT)
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    try:
        mujoco.mj_fullM(model, data, np.zeros((model.nv, model.nv)))  # type: ignore[arg-type, unused-ignore]
    except TypeError:
        return False
    return True


def joint_type_membership_fails() -> bool:
    """Whether a joint type read from a model (a numpy integer) is not ``in`` a tuple of ``mjtJoint``s."""
    model = mujoco.MjModel.from_xml_string(ONE_JOINT)
    hinge, slide = mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE
    return model.jnt_type[0] not in (hinge, slide)


def always() -> bool:
    """The replacement works on every MuJoCo (it compares plain integers)."""
    return True


@dataclass(frozen=True)
class Patch:
    """One statement of a robosuite method, replaced when this MuJoCo cannot run it."""

    name: str
    module: str
    owner: str
    method: str
    old: str
    new: str
    needed: Callable[[], bool]
    """Whether robosuite's statement fails on this MuJoCo."""
    possible: Callable[[], bool]
    """Whether the replacement works on this MuJoCo."""

    @property
    def where(self) -> str:
        """The method's dotted name."""
        return f"{self.module}.{self.owner}.{self.method}"


JOINT_TYPE_ASSERT = "assert joint_type in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)"
INTEGER_JOINT_TYPE_ASSERT = (
    "assert int(joint_type) in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)"
)

PATCHES: tuple[Patch, ...] = (
    Patch(
        "mass-matrix",
        "robosuite.controllers.parts.controller",
        "Controller",
        "update",
        old="mujoco.mj_fullM(self.sim.model._model, mass_matrix, self.sim.data.qM)",
        new="mujoco.mj_fullM(self.sim.model._model, self.sim.data._data, mass_matrix)",
        needed=robosuites_mass_matrix_call_fails,
        possible=new_mass_matrix_call_works,
    ),
    *(
        Patch(
            f"joint-{kind}-address",
            "robosuite.utils.binding_utils",
            "MjModel",
            f"get_joint_{kind}_addr",
            old=JOINT_TYPE_ASSERT,
            new=INTEGER_JOINT_TYPE_ASSERT,
            needed=joint_type_membership_fails,
            possible=always,
        )
        for kind in ("qpos", "qvel")
    ),
)
"""Every patch, in the order they are applied."""


class RobosuiteChanged(Exception):
    """robosuite no longer holds the statement a patch replaces (said, not raised to the user)."""


def _method(patch: Patch) -> FunctionType:
    """robosuite's method the patch rewrites (:class:`RobosuiteChanged` where robosuite has none)."""
    try:
        module = importlib.import_module(patch.module)
    except ImportError:
        raise RobosuiteChanged(f"robosuite has no module {patch.module}") from None
    owner = getattr(module, patch.owner, None)
    method = getattr(owner, patch.method, None)
    if not isinstance(method, FunctionType):
        raise RobosuiteChanged(f"robosuite has no {patch.where}")
    return method


def _rewritten(patch: Patch, method: FunctionType) -> FunctionType:
    """``method`` with ``patch.old`` replaced by ``patch.new``, compiled in its module at its lines."""
    try:
        lines, first_line = inspect.getsourcelines(method)
    except (OSError, TypeError):
        raise RobosuiteChanged(f"the source of {patch.where} cannot be read") from None
    source = textwrap.dedent("".join(lines))
    count = source.count(patch.old)
    if count != 1 or not source.startswith("def ") or method.__code__.co_freevars:
        raise RobosuiteChanged(f"{patch.where} no longer holds `{patch.old}` once")
    code = compile(
        "\n" * (first_line - 1) + source.replace(patch.old, patch.new), method.__code__.co_filename, "exec"
    )
    namespace: dict[str, object] = {}
    exec(code, method.__globals__, namespace)  # the module's own globals: robosuite's `mujoco`, `np`
    made = namespace[method.__name__]
    assert isinstance(made, FunctionType)
    made.__qualname__, made.__module__, made.__doc__ = method.__qualname__, method.__module__, method.__doc__
    made.__defaults__, made.__kwdefaults__ = method.__defaults__, method.__kwdefaults__
    setattr(made, PATCHED, patch.name)
    return made


def state(patch: Patch) -> str:
    """What the patch does on this MuJoCo and this robosuite, in a few words."""
    try:
        method = _method(patch)
    except RobosuiteChanged as changed:
        return f"skipped: {changed}"
    if getattr(method, PATCHED, None) == patch.name:
        return "applied"
    try:
        _rewritten(patch, method)
    except RobosuiteChanged as changed:
        return f"skipped: {changed}"
    if not patch.needed():
        return f"not needed: robosuite's statement runs on MuJoCo {mujoco.__version__}"
    if not patch.possible():
        return (
            f"skipped: neither robosuite's statement nor its replacement runs on MuJoCo {mujoco.__version__}"
        )
    return "not applied yet"


def apply(patch: Patch) -> str:
    """Apply ``patch`` where this MuJoCo needs it; its state afterwards."""
    before = state(patch)
    if before != "not applied yet":
        return before
    method = _method(patch)
    setattr(
        getattr(importlib.import_module(patch.module), patch.owner), patch.method, _rewritten(patch, method)
    )
    return "applied"


def apply_all() -> dict[str, str]:
    """Apply every patch this MuJoCo needs (robosuite must be importable); a patch this MuJoCo needs but
    robosuite's code no longer allows is said in one line on standard error. Returns each patch's state."""
    states: dict[str, str] = {}
    for patch in PATCHES:
        states[patch.name] = said = apply(patch)
        if said.startswith("skipped") and patch.needed():
            print(
                f"assembler.robosuite: patch {patch.name} {said}; "
                f"robosuite may fail on MuJoCo {mujoco.__version__}",
                file=sys.stderr,
            )
    return states


def report() -> list[str]:
    """One line per patch: its name, where it applies, its state (``--check``)."""
    return [f"{patch.name} ({patch.where}): {state(patch)}" for patch in PATCHES]
