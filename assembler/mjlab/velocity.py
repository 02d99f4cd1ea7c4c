"""``use_robot(cfg, robot)``: a spec robot in mjlab's own velocity task, its per-robot slots filled.

mjlab's ``make_velocity_env_cfg()`` is its velocity task for any robot: it leaves the robot's entity and
the names it reads of it empty ("Set per-robot"), and its Go1 and G1 configs fill them. This fills the
same slots for a spec robot, and nothing else of the task: the entity (:func:`entity_cfg`), the feet
contact sensor, the root body (terrain scan frame, base COM, upright and body angular-velocity terms,
viewer), the feet's sites (foot height scan, clearance and slip terms) and collision geoms (friction
randomization), the posture reward's per-joint spreads, and the joint-position action's scale per joint
(mjlab's rule for its robots: 0.25 × a servo's force limit / its stiffness).
"""

from __future__ import annotations

import re

import mujoco
from mjlab.envs import ManagerBasedRlEnvCfg
from mjlab.envs.mdp.actions import JointPositionActionCfg
from mjlab.sensor import ObjRef, RayCastSensorCfg, RingPatternCfg, TerrainHeightSensorCfg

from assembler.mjlab.entity import entity_cfg, for_mjlab, force_limit, is_position_servo
from assembler.mjlab.task_parts import task_parts
from assembler.models import RobotModel

ACTION_SCALE = 0.25
"""mjlab's G1, Go1 and YAM configs scale each joint's position action to 0.25 × its servo's effort limit
over its stiffness: an action of 1 asks a quarter of the joint's torque limit."""


def action_scale(model: mujoco.MjModel) -> dict[str, float] | None:
    """Per actuated joint (its exact name as a pattern), :data:`ACTION_SCALE` × force limit / kp; None
    unless every actuator is a position servo with a force limit (the rule needs both)."""
    scale: dict[str, float] = {}
    for actuator in range(model.nu):
        kp, limit = float(model.actuator_gainprm[actuator, 0]), force_limit(model, actuator)
        if not is_position_servo(model, actuator) or kp <= 0 or limit is None:
            return None
        joint = model.joint(int(model.actuator_trnid[actuator, 0])).name
        scale[re.escape(joint)] = ACTION_SCALE * limit / kp
    return scale


POSTURE_STD = {"std_standing": 0.05, "std_walking": 0.3, "std_running": 0.5}
"""The posture reward's spread for every joint: mjlab's G1 standing value (0.05 for all joints), and its
hip-pitch values walking (0.3) and running (0.5)."""


def use_robot(
    cfg: ManagerBasedRlEnvCfg, robot: RobotModel | str, entity: str = "robot"
) -> ManagerBasedRlEnvCfg:
    """mjlab's velocity task config ``cfg`` (``make_velocity_env_cfg()``) with ``robot`` as its entity
    ``entity`` and every per-robot slot filled from the robot's spec; changed in place and returned."""
    model = for_mjlab(robot) if isinstance(robot, str) else robot
    compiled = model.get_model()
    parts = task_parts(model, compiled)
    action, scale = cfg.actions.get("joint_pos"), action_scale(compiled)
    if isinstance(action, JointPositionActionCfg) and scale is not None:
        action.scale = scale
    cfg.scene.entities = {**cfg.scene.entities, entity: entity_cfg(model)}
    sites = tuple(re.escape(site) for _, site, _ in parts.feet)
    root = re.escape(parts.root)
    for sensor in cfg.scene.sensors:
        if (
            isinstance(sensor, RayCastSensorCfg)
            and isinstance(sensor.frame, ObjRef)
            and not sensor.frame.name
        ):
            sensor.frame.name = parts.root
        if isinstance(sensor, TerrainHeightSensorCfg) and not sensor.frame:
            sensor.frame = tuple(ObjRef(type="site", name=s, entity=entity) for _, s, _ in parts.feet)
            sensor.pattern = RingPatternCfg.single_ring(radius=0.03, num_samples=6)  # mjlab's G1 ring
    cfg.scene.sensors = (*cfg.scene.sensors, parts.feet_sensor(entity))
    terms = {**cfg.events, **cfg.rewards}
    for term in terms.values():
        asset = term.params.get("asset_cfg")
        if asset is None or asset.name != entity:
            continue
        if asset.body_names == ():
            asset.body_names = (root,)
        if asset.site_names == ():
            asset.site_names = sites
        if asset.geom_names == ():
            asset.geom_names = tuple(re.escape(g) for g in parts.foot_geoms)
    posture = cfg.rewards.get("pose")
    if posture is not None:
        for key, spread in POSTURE_STD.items():
            if posture.params.get(key) == {}:
                posture.params[key] = {".*": spread}
    if not cfg.viewer.body_name:
        cfg.viewer.body_name = parts.root
    return cfg
