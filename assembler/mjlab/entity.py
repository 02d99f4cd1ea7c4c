"""``entity_cfg``: an assembled robot as an mjlab ``EntityCfg`` (spec, actuators, home pose).

- ``spec_fn`` returns a fresh copy of the robot's assembled ``MjSpec`` on every call (mjlab edits
  and attaches what it gets), without keyframes: mjlab writes its own ``init_state`` key.
- Actuators: ``"xml"`` wraps the actuators the assembly already has (``XmlActuatorCfg``, one entry
  naming exactly the actuated joints, so mjlab does not also match sites); ``"builtin"`` maps each
  position servo and motor to mjlab's ``BuiltinPositionActuatorCfg``/``BuiltinMotorActuatorCfg`` with
  the compiled gains and force limits, and ``spec_fn`` then leaves the assembly's actuators out.
- ``init_state`` holds the home pose joint by joint. mjlab's ``joint_pos=None`` (take the spec's
  keyframe) fails at reset on a float64/float32 mismatch in mjlab 1.6.0, so the pose is always given.
- The spec's ``mjlab:`` block (:mod:`~assembler.mjlab.task_parts`) adds the IMU and the feet, sets the
  soft joint-limit factor, the geoms' contact settings (:mod:`~assembler.mjlab.collisions`) and the
  spawn pose; a robot given by name is
  assembled with the joint rules its spec writes only (robosuite's with ``mjlab.joint_rules: robosuite``)
  and with a free joint or without as ``mjlab.floating`` says.
"""

from __future__ import annotations

import re
from collections.abc import Callable
from typing import Literal

import mujoco
from mjlab.actuator import (
    BuiltinDcMotorActuatorCfg,
    BuiltinMotorActuatorCfg,
    BuiltinPositionActuatorCfg,
    DcMotorInputMode,
    DcMotorPhysicalParams,
    XmlActuatorCfg,
)
from mjlab.actuator.actuator import ActuatorCfg
from mjlab.entity import EntityArticulationInfoCfg, EntityCfg
from mjlab.sensor import ContactSensorCfg

from assembler.compiler.keyframe import HOME_KEY
from assembler.errors import AssemblerError, Problem
from assembler.mjlab.collisions import Collisions, collisions
from assembler.mjlab.task_parts import TaskParts, task_parts
from assembler.models import RobotModel
from assembler.registry.instances import assemble, robot_class
from assembler.spec.schema.joints import JOINT_RULE_ATTRIBUTES

ActuatorChoice = Literal["xml", "builtin"]
"""``xml``: mjlab drives the assembly's own actuators; ``builtin``: mjlab's built-in configs replace them."""

JOINT = mujoco.mjtObj.mjOBJ_JOINT
SCALAR_JOINTS = (int(mujoco.mjtJoint.mjJNT_HINGE), int(mujoco.mjtJoint.mjJNT_SLIDE))


def _exact(name: str) -> str:
    """A regular expression matching ``name`` only (mjlab matches names with ``re.fullmatch``)."""
    return re.escape(name)


def home_joint_positions(model: mujoco.MjModel) -> tuple[tuple[float, ...] | None, dict[str, float]]:
    """The home keyframe as mjlab's init_state: the free joint's (pos, quat) if the robot floats, and
    each hinge or slide joint's position."""
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    qpos = model.key_qpos[key] if key >= 0 else model.qpos0
    root: tuple[float, ...] | None = None
    positions: dict[str, float] = {}
    for joint in range(model.njnt):
        address, kind = int(model.jnt_qposadr[joint]), int(model.jnt_type[joint])
        name = mujoco.mj_id2name(model, JOINT, joint) or f"joint #{joint}"
        if kind == int(mujoco.mjtJoint.mjJNT_FREE):
            root = tuple(float(v) for v in qpos[address : address + 7])
        elif kind in SCALAR_JOINTS:
            positions[name] = float(qpos[address])
        else:
            raise AssemblerError(
                f"{name}: a ball joint; mjlab's init_state sets one position per joint (hinge or slide)"
            )
    return root, positions


def force_limit(model: mujoco.MjModel, actuator: int) -> float | None:
    """The actuator's largest force magnitude, or None when its force is not limited."""
    if not model.actuator_forcelimited[actuator]:
        return None
    return float(max(abs(v) for v in model.actuator_forcerange[actuator]))


def is_position_servo(model: mujoco.MjModel, actuator: int) -> bool:
    """A position servo without dynamics: fixed gain kp, affine bias -kp·q - kv·qdot."""
    gain, bias = model.actuator_gainprm[actuator], model.actuator_biasprm[actuator]
    return (
        int(model.actuator_dyntype[actuator]) == int(mujoco.mjtDyn.mjDYN_NONE)
        and int(model.actuator_gaintype[actuator]) == int(mujoco.mjtGain.mjGAIN_FIXED)
        and int(model.actuator_biastype[actuator]) == int(mujoco.mjtBias.mjBIAS_AFFINE)
        and bias[1] == -gain[0]
        and bias[0] == 0
    )


def _voltage_motor(model: mujoco.MjModel, actuator: int) -> DcMotorPhysicalParams | None:
    """The motor of a DC motor taking volts as ``control: voltage`` makes it (MuJoCo's ``dcmotor`` with
    its motor constant and resistance and nothing else: gainprm [R, K], no saturation, controller,
    inductance or friction), or None."""
    dcmotor = getattr(mujoco.mjtGain, "mjGAIN_DCMOTOR", None)
    if dcmotor is None or int(model.actuator_gaintype[actuator]) != int(dcmotor):
        return None
    gain = model.actuator_gainprm[actuator]
    if gain[2:].any() or model.actuator_biasprm[actuator].any() or model.actuator_dynprm[actuator].any():
        return None
    resistance, constant = float(gain[0]), float(gain[1])
    return DcMotorPhysicalParams(kt=constant, ke=constant, resistance=resistance)


def mapped_actuators(model: mujoco.MjModel) -> tuple[ActuatorCfg, ...]:
    """mjlab built-in configs for the model's actuators: position servos (kp, kv, force limit), motors
    (gear, force limit) and DC motors taking volts (motor constant, resistance, gear: mjlab's own
    ``dcmotor`` in voltage mode), one per actuated joint; any other kind is refused, by name."""
    configs: list[ActuatorCfg] = []
    problems: list[str] = []
    fixed = int(mujoco.mjtGain.mjGAIN_FIXED)
    for actuator in range(model.nu):
        name = mujoco.mj_id2name(model, mujoco.mjtObj.mjOBJ_ACTUATOR, actuator) or f"actuator #{actuator}"
        if int(model.actuator_trntype[actuator]) != int(mujoco.mjtTrn.mjTRN_JOINT):
            problems.append(
                f"{name}: drives no joint (mjlab's built-in actuators drive joints); use actuators='xml'"
            )
            continue
        joint = mujoco.mj_id2name(model, JOINT, int(model.actuator_trnid[actuator, 0]))
        gain, bias = model.actuator_gainprm[actuator], model.actuator_biasprm[actuator]
        gaintype, biastype = int(model.actuator_gaintype[actuator]), int(model.actuator_biastype[actuator])
        gear, limit = float(model.actuator_gear[actuator, 0]), force_limit(model, actuator)
        direct = int(model.actuator_dyntype[actuator]) == int(mujoco.mjtDyn.mjDYN_NONE)
        if is_position_servo(model, actuator) and gear == 1.0:
            configs.append(
                BuiltinPositionActuatorCfg(
                    target_names_expr=(_exact(joint),),
                    stiffness=float(gain[0]),
                    damping=float(-bias[2]),
                    effort_limit=limit,
                )
            )
        elif direct and gaintype == fixed and gain[0] == 1.0 and biastype == int(mujoco.mjtBias.mjBIAS_NONE):
            if limit is None:
                problems.append(f"{name}: a motor without forcerange; mjlab's motor needs an effort limit")
                continue
            configs.append(
                BuiltinMotorActuatorCfg(target_names_expr=(_exact(joint),), effort_limit=limit, gear=gear)
            )
        elif (motor := _voltage_motor(model, actuator)) is not None:
            configs.append(
                BuiltinDcMotorActuatorCfg(
                    target_names_expr=(_exact(joint),),
                    motor_params=motor,
                    mode=DcMotorInputMode.VOLTAGE,
                    gear=gear,
                    effort_limit=limit,
                )
            )
        else:
            problems.append(
                f"{name}: neither a position servo, a motor nor a DC motor taking volts (gain {gaintype}, "
                f"bias {biastype}); use actuators='xml' to keep it as it is"
            )
    if problems:
        raise AssemblerError([Problem(p) for p in problems])
    return tuple(configs)


def _spec_fn(
    robot: RobotModel, keep_actuators: bool, parts: TaskParts, contacts: Collisions
) -> Callable[[], mujoco.MjSpec]:
    def spec() -> mujoco.MjSpec:
        copy = robot.mjspec.copy()
        for key in list(copy.keys):
            copy.delete(key)
        if not keep_actuators:
            for actuator in list(copy.actuators):
                copy.delete(actuator)
        parts.edit(copy, contacts.unnamed)
        return copy

    return spec


def _has_free_joint(model: mujoco.MjModel) -> bool:
    return any(int(t) == int(mujoco.mjtJoint.mjJNT_FREE) for t in model.jnt_type)


def for_mjlab(name: str) -> RobotModel:
    """Robot ``name`` assembled as its spec's ``mjlab:`` block asks: the joint default rules the spec
    writes only (robosuite's too with ``joint_rules: robosuite``), floating or welded per ``floating``."""
    spec = robot_class(name).spec
    options = spec.mjlab
    overrides: list[str] = []
    if options.joint_rules == "spec":
        written = spec.joint_defaults.model_fields_set if "joint_defaults" in spec.model_fields_set else set()
        overrides += [f"joint_defaults.{a}=null" for a in JOINT_RULE_ATTRIBUTES if a not in written]
    model = assemble(name, overrides=overrides or None)
    if options.floating is None or _has_free_joint(model.get_model()) == options.floating:
        return model
    if not options.floating:
        return assemble(name, overrides=[*overrides, "remove_free_joint=true"])
    model = assemble(name, overrides=[*overrides, "remove_free_joint=false"])
    if _has_free_joint(model.get_model()):
        return model
    return assemble(name, overrides=[*overrides, "add_free_joint=true"])


def entity_cfg(
    robot: RobotModel | str,
    actuators: ActuatorChoice = "xml",
    pos: tuple[float, float, float] | None = None,
) -> EntityCfg:
    """The robot (a RobotModel as assembled, or a registered name assembled by :func:`for_mjlab`) as an
    mjlab ``EntityCfg``: its spec with the IMU and feet its ``mjlab:`` block asks for, the contact
    settings it declares (``collisions``, ``foot_friction``, ``foot_condim``), its actuators
    (``actuators``), its home pose as ``init_state``, the root at ``pos`` when given, else at
    ``mjlab.spawn_pos``, else standing on the floor if it floats (its lowest collision point at z = 0)
    or where the home pose puts it if it is welded."""
    model = for_mjlab(robot) if isinstance(robot, str) else robot
    compiled = model.get_model()
    parts = task_parts(model, compiled)
    contacts = collisions(model, compiled, parts)
    root, joint_pos = home_joint_positions(compiled)
    actuated = [
        mujoco.mj_id2name(compiled, JOINT, int(compiled.actuator_trnid[a, 0]))
        for a in range(compiled.nu)
        if int(compiled.actuator_trntype[a]) == int(mujoco.mjtTrn.mjTRN_JOINT)
    ]
    if actuators == "xml":
        configs: tuple[ActuatorCfg, ...] = (
            (XmlActuatorCfg(target_names_expr=tuple(_exact(j) for j in actuated)),) if actuated else ()
        )
    else:
        configs = mapped_actuators(compiled)
    state = EntityCfg.InitialStateCfg(joint_pos={_exact(j): v for j, v in joint_pos.items()})
    if root is not None:
        state.pos = (root[0], root[1], root[2] - parts.lowest)
        state.rot = (root[3], root[4], root[5], root[6])
    spawn = pos if pos is not None else model.spec.mjlab.spawn_pos
    if spawn is not None:
        state.pos = spawn
    return EntityCfg(
        spec_fn=_spec_fn(model, keep_actuators=actuators == "xml", parts=parts, contacts=contacts),
        articulation=EntityArticulationInfoCfg(
            actuators=configs, soft_joint_pos_limit_factor=model.spec.mjlab.soft_joint_pos_limit_factor
        ),
        init_state=state,
        collisions=contacts.configs,
    )


def feet_sensor(robot: RobotModel | str, entity: str = "robot") -> ContactSensorCfg:
    """The feet contact sensor mjlab's velocity task reads (``feet_ground_contact``) for the robot as
    :func:`entity_cfg` makes it, scoped to the scene entity named ``entity``."""
    model = for_mjlab(robot) if isinstance(robot, str) else robot
    return task_parts(model, model.get_model()).feet_sensor(entity)
