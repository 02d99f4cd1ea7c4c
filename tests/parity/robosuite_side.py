"""robosuite's side of a case: the model assembled the way ``robosuite.robots.Robot.load_model`` does
(robots/robot.py:161-223), placed and edited with robosuite's own ``set_base_xpos``, ``set_base_ori``
and ``set_joint_attribute``, compiled by MuJoCo; and the pose robosuite resets the robot to."""

from __future__ import annotations

import hashlib
import os
import tempfile
from collections.abc import Callable
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import mujoco
import numpy as np

from tests.parity import case as case_module
from tests.parity.case import DEFAULT, Case, joint_attribute_values


@dataclass(frozen=True)
class Reference:
    """robosuite's compiled model, and the ``home`` keyframe ours must hold: the joint positions
    robosuite's ``Robot.reset`` writes (robot, grippers, legs) and the controls holding them."""

    model: mujoco.MjModel
    home_qpos: np.ndarray
    home_ctrl: np.ndarray


def _assemble(case: Case) -> tuple[Any, dict[str, Any]]:
    """robosuite's RobotModel of the case and its gripper per arm (not yet placed)."""
    from robosuite.models.bases import robot_base_factory
    from robosuite.models.grippers import gripper_factory
    from robosuite.models.robots import create_robot
    from robosuite.utils.mjcf_utils import array_to_string

    model = create_robot(case.robot, idn=case.idn)
    base_name = model.default_base if case.base == DEFAULT else case.base
    if base_name is not None:
        model.add_base(robot_base_factory(base_name, idn=case.idn))
    grippers = {}
    for arm in model.arms:
        name = model.default_gripper[arm] if case.gripper is None else case.gripper
        gripper = gripper_factory(None if name == "NullGripper" else name, idn=f"{case.idn}_{arm}")
        root = gripper.worldbody.find("body")
        if arm in model.gripper_mount_pos_offset:
            root.set("pos", array_to_string(model.gripper_mount_pos_offset[arm]))
        if arm in model.gripper_mount_quat_offset:
            root.set("quat", array_to_string(model.gripper_mount_quat_offset[arm]))
        model.add_gripper(gripper, model.eef_name[arm])
        grippers[arm] = gripper
    return model, grippers


def robosuite_xml(case: Case | str) -> str:
    """robosuite's MJCF text of the case (or of a robot with its defaults)."""
    return str(_placed(Case(case) if isinstance(case, str) else case)[0].get_xml())


def robosuite_robot_model(robot: str) -> Any:
    """robosuite's robot model of a robot with its defaults (its ``get_xml`` not called)."""
    return _placed(Case(robot))[0]


def robosuite_model(robot: str) -> mujoco.MjModel:
    """robosuite's compiled model of a robot with its defaults."""
    return mujoco.MjModel.from_xml_string(robosuite_xml(robot))


def _placed(case: Case) -> tuple[Any, dict[str, Any]]:
    model, grippers = _assemble(case)
    if case.xpos is not None:
        model.set_base_xpos(np.array(case.xpos))
    if case.ori is not None:
        model.set_base_ori(np.array(case.ori))
    if case.joint_attribute is not None:
        attribute, force = case.joint_attribute
        model.set_joint_attribute(attribute, joint_attribute_values(model.dof), force=force)
    return model, grippers


def build_reference(case: Case) -> Reference:
    """robosuite's compiled model of the case and the keyframe robosuite's reset implies, from the
    reference store when this robosuite, this MuJoCo and this module made it before (see
    :func:`reference_folder`), else built and stored."""
    folder = reference_folder()
    if folder is None:
        return build_edited_reference(case, None)
    stored = folder / f"{_reference_key(case)}.npz"
    if stored.is_file():
        with np.load(stored) as saved:
            model = _model_from_bytes(saved["model"].tobytes())
            return Reference(model, saved["home_qpos"], saved["home_ctrl"])
    reference = build_edited_reference(case, None)
    folder.mkdir(parents=True, exist_ok=True)
    handle, temporary = tempfile.mkstemp(dir=folder, suffix=".npz.tmp")
    with os.fdopen(handle, "wb") as stream:
        np.savez(
            stream,
            model=np.frombuffer(_model_bytes(reference.model), np.uint8),
            home_qpos=reference.home_qpos,
            home_ctrl=reference.home_ctrl,
        )
    os.replace(temporary, stored)  # whole or absent: parallel workers may store the same case
    return reference


REFERENCE_FOLDER_VARIABLE = "PARITY_REFERENCE_DIR"
"""Where robosuite's compiled side of the parity cases is kept between runs; ``off`` builds every
reference each time. Default: ``robot-assembler-parity`` in the user's cache folder. robosuite's side
does not change unless robosuite, MuJoCo or this module does, and building it is most of a case's
time, so CI keeps it (it is rebuilt on any miss)."""


def reference_folder() -> Path | None:
    """The folder of stored references, or None when storing is off."""
    chosen = os.environ.get(REFERENCE_FOLDER_VARIABLE)
    if chosen == "off":
        return None
    if chosen:
        return Path(chosen)
    base = os.environ.get("XDG_CACHE_HOME") or str(Path.home() / ".cache")
    return Path(base) / "robot-assembler-parity"


def _reference_key(case: Case) -> str:
    """The stored reference's name: robosuite's and MuJoCo's versions, the case, and this module's
    own text (the way the reference is built)."""
    import robosuite

    made_by = Path(__file__).read_bytes() + Path(case_module.__file__).read_bytes()
    text = repr((robosuite.__version__, mujoco.__version__, case, hashlib.sha256(made_by).hexdigest()))
    return hashlib.sha256(text.encode()).hexdigest()[:32]


def _model_bytes(model: mujoco.MjModel) -> bytes:
    buffer = np.zeros(mujoco.mj_sizeModel(model), np.uint8)
    mujoco.mj_saveModel(model, None, buffer)
    return buffer.tobytes()


def _model_from_bytes(data: bytes) -> mujoco.MjModel:
    with tempfile.NamedTemporaryFile(suffix=".mjb") as stream:
        stream.write(data)
        stream.flush()
        return mujoco.MjModel.from_binary_path(stream.name)


def normalized(case: Case) -> Case:
    """The case with robosuite's defaults spelled out: cases equal after this assemble the same
    model in robosuite (e.g. Panda, and Panda with PandaGripper), so one compile serves them all."""
    from robosuite.models.robots import create_robot

    defaults = create_robot(case.robot, idn=case.idn)
    grippers = {defaults.default_gripper[arm] for arm in defaults.arms}
    gripper = case.gripper or (grippers.pop() if len(grippers) == 1 else None)
    return replace(case, base=defaults.default_base if case.base == DEFAULT else case.base, gripper=gripper)


def build_edited_reference(case: Case, edit: Callable[[Any], object] | None) -> Reference:
    """:func:`build_reference`, with ``edit`` changing robosuite's RobotModel (its XML tree) before
    it is compiled (the oracle's own tests)."""
    robot, grippers = _placed(case)
    if edit is not None:
        edit(robot)
    model = mujoco.MjModel.from_xml_string(robot.get_xml())
    qpos = model.qpos0.copy()
    parts = [(robot.joints, robot.init_qpos)]
    # A NullGripper has no init_qpos (None); robosuite's reset skips it (robots/robot.py:285).
    parts += [(g.joints, g.init_qpos) for g in grippers.values() if g.init_qpos is not None]
    from robosuite.models.bases.leg_base_model import LegBaseModel

    if isinstance(robot.base, LegBaseModel) and len(robot.base.init_qpos):  # legged_robot.py:132-134
        legs = [joint for joint in robot.base.joints if "leg" in joint.removeprefix(robot.base.naming_prefix)]
        parts.append((legs, robot.base.init_qpos))
    for joints, values in parts:
        for joint, value in zip(joints, np.atleast_1d(values), strict=True):
            qpos[model.jnt_qposadr[model.joint(joint).id]] = value
    return Reference(model, qpos, holding_controls(model, qpos))


def holding_controls(model: mujoco.MjModel, qpos: np.ndarray) -> np.ndarray:
    """The controls that make each position actuator (force ``kp * (ctrl - q)`` on one joint) hold
    ``qpos``, within its control range; zero for every other actuator."""
    ctrl = np.zeros(model.nu)
    for actuator in range(model.nu):
        kp = model.actuator_gainprm[actuator, 0]
        on_joint = model.actuator_trntype[actuator] == mujoco.mjtTrn.mjTRN_JOINT
        if on_joint and kp > 0 and np.isclose(model.actuator_biasprm[actuator, 1], -kp):
            target = qpos[model.jnt_qposadr[model.actuator_trnid[actuator, 0]]]
            if model.actuator_ctrllimited[actuator]:
                target = np.clip(target, *model.actuator_ctrlrange[actuator])
            ctrl[actuator] = target
    return ctrl
