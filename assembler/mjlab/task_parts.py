"""What mjlab's tasks read of a robot, from its spec's ``mjlab:`` block: an IMU, feet, a spawn height.

- The IMU is a site (``<prefix>imu``) on ``mjlab.imu_body`` (default: the root) with the sensors mjlab's
  velocity task reads by name, as mjlab's own Go1 and G1 carry them: ``imu_ang_vel`` (gyro),
  ``imu_lin_vel`` (velocimeter) and ``root_angmom`` (the root's subtree angular momentum). mjlab scopes
  them under the entity (``robot/imu_lin_vel``), so they carry no robot prefix.
- Each foot (``mjlab.feet``, else the spec's ``feet``) gets a site ``<foot body>_sole`` at its lowest
  collision point at the home pose, for the task's foot terms, a name ``<foot body>_geom<i>`` for each
  of its collision geoms that has none (a URDF's; mjlab selects geoms by name), and the feet contact sensor
  (``feet_ground_contact``: the feet's subtrees against the terrain, as mjlab's G1 task builds it).
- A floating robot spawns with its lowest collision point on the floor (z = 0) at the home pose, and its
  root body is raised or lowered so that it also stands on the floor at ``qpos0`` (all joints at 0), as
  mjlab's own robots do: mjlab hands MuJoCo Warp the contacts of ``qpos0``, and a model whose feet
  sink into the terrain there overflows the task's ``nconmax`` before the first step.
"""

from __future__ import annotations

import difflib
import re
from collections.abc import Collection
from dataclasses import dataclass

import mujoco
import numpy as np
from mjlab.sensor import ContactMatch, ContactSensorCfg
from numpy.typing import NDArray

from assembler.compiler.keyframe import HOME_KEY
from assembler.errors import AssemblerError, Problem
from assembler.models import RobotModel

BODY = mujoco.mjtObj.mjOBJ_BODY
FEET_SENSOR = "feet_ground_contact"
"""The name mjlab's velocity task reads the feet contact sensor by."""
IMU_SENSORS = (
    ("imu_ang_vel", mujoco.mjtSensor.mjSENS_GYRO),
    ("imu_lin_vel", mujoco.mjtSensor.mjSENS_VELOCIMETER),
)
"""The IMU site's sensors, named as mjlab's velocity task reads them (``robot/imu_lin_vel``, ...)."""
ANGMOM_SENSOR = "root_angmom"
"""The root's subtree angular momentum, named as mjlab's velocity task reads it."""


@dataclass(frozen=True)
class TaskParts:
    """Where the IMU and the feet go (compiled names, positions in their body's frame), and the root."""

    root: str
    imu_body: str
    imu_site: str
    imu_pos: tuple[float, float, float]
    feet: tuple[tuple[str, str, tuple[float, float, float]], ...]
    """(body, site, position) per foot."""
    foot_geoms: tuple[str, ...]
    lowest: float
    """The lowest collision point's height at the home pose, in the compiled model's frame."""
    lift: float
    """How far a floating root body is raised to put its lowest point at z = 0 at ``qpos0`` (0: welded)."""

    def edit(self, spec: mujoco.MjSpec, unnamed: Collection[str] = ()) -> None:
        """Add the IMU site and its sensors and the feet's sites to ``spec`` (a copy of the assembly's), and
        name its feet's unnamed collision geoms and the ``unnamed`` ones (``<body>_geom<i>`` names)."""
        if self.lift:
            root = spec.body(self.root)
            root.pos = [root.pos[0], root.pos[1], root.pos[2] + self.lift]
        spec.body(self.imu_body).add_site(name=self.imu_site, pos=list(self.imu_pos), group=5)
        for name, kind in IMU_SENSORS:
            spec.add_sensor(name=name, type=kind, objtype=mujoco.mjtObj.mjOBJ_SITE, objname=self.imu_site)
        spec.add_sensor(
            name=ANGMOM_SENSOR, type=mujoco.mjtSensor.mjSENS_SUBTREEANGMOM, objtype=BODY, objname=self.root
        )
        for body, site, pos in self.feet:
            spec.body(body).add_site(name=site, pos=list(pos), group=5)
        wanted = {*self.foot_geoms, *unnamed}
        for body in spec.bodies:
            for place, geom in enumerate(body.geoms):  # in the compiled model's order
                if not geom.name and unnamed_geom_name(body.name, place) in wanted:
                    geom.name = unnamed_geom_name(body.name, place)

    def feet_sensor(self, entity: str = "robot") -> ContactSensorCfg:
        """The feet contact sensor mjlab's velocity task reads (``feet_ground_contact``), as its G1's."""
        return ContactSensorCfg(
            name=FEET_SENSOR,
            primary=ContactMatch(
                mode="subtree", pattern=tuple(re.escape(b) for b, _, _ in self.feet), entity=entity
            ),
            secondary=ContactMatch(mode="body", pattern="terrain"),
            fields=("found", "force"),
            reduce="netforce",
            num_slots=1,
            track_air_time=True,
        )


def mjlab_geom_name(model: mujoco.MjModel, geom: int) -> str:
    """A geom's name in mjlab's copy of the robot: its own, or (unnamed) :func:`unnamed_geom_name`."""
    body = int(model.geom_bodyid[geom])
    return model.geom(geom).name or unnamed_geom_name(
        model.body(body).name, geom - int(model.body_geomadr[body])
    )


def unnamed_geom_name(body: str, place: int) -> str:
    """The name an unnamed geom (a foot's, or one ``mjlab.collisions`` selects) gets in mjlab's copy of the
    robot (a URDF's collision geoms have none; mjlab selects geoms by name): its body's name and its place
    among that body's geoms."""
    return f"{body}_geom{place}"


def _body(model: mujoco.MjModel, prefix: str, name: str, field: str) -> str:
    full = prefix + name
    if mujoco.mj_name2id(model, BODY, full) >= 0:
        return full
    known = [n[len(prefix) :] for b in range(1, model.nbody) if (n := model.body(b).name).startswith(prefix)]
    close = difflib.get_close_matches(name, known, n=1)
    hint = (
        f" Did you mean '{close[0]}'?"
        if close
        else f" Bodies: {', '.join(known[:8])}{' ...' if len(known) > 8 else ''}"
    )
    raise AssemblerError(f"mjlab.{field}: no body '{name}' in the robot.{hint}")


def _collides(model: mujoco.MjModel, geom: int) -> bool:
    return bool(model.geom_contype[geom] or model.geom_conaffinity[geom])


def geom_lowest(model: mujoco.MjModel, data: mujoco.MjData, geom: int) -> float:
    """The lowest world height of ``geom`` (exact for spheres, capsules, boxes, cylinders and meshes;
    an ellipsoid by its box)."""
    kind, size = int(model.geom_type[geom]), model.geom_size[geom]
    centre, frame = data.geom_xpos[geom], data.geom_xmat[geom].reshape(3, 3)
    axis_z = frame[2]  # each local axis's world z component
    t = mujoco.mjtGeom
    if kind == t.mjGEOM_SPHERE:
        return float(centre[2] - size[0])
    if kind == t.mjGEOM_CAPSULE:
        return float(centre[2] - abs(axis_z[2]) * size[1] - size[0])
    if kind == t.mjGEOM_CYLINDER:
        return float(centre[2] - abs(axis_z[2]) * size[1] - size[0] * np.sqrt(max(0.0, 1 - axis_z[2] ** 2)))
    if kind == t.mjGEOM_MESH:
        mesh = int(model.geom_dataid[geom])
        start, count = int(model.mesh_vertadr[mesh]), int(model.mesh_vertnum[mesh])
        vertices: NDArray[np.float64] = model.mesh_vert[start : start + count].astype(np.float64)
        return float(centre[2] + (vertices @ axis_z).min())
    if kind in (t.mjGEOM_BOX, t.mjGEOM_ELLIPSOID):
        return float(centre[2] - np.abs(axis_z) @ size)
    return float(centre[2])  # a plane or heightfield belongs to no robot


def home_data(model: mujoco.MjModel) -> mujoco.MjData:
    """The model's data at its home keyframe (or qpos0), kinematics computed."""
    data = mujoco.MjData(model)
    key = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
    if key >= 0:
        mujoco.mj_resetDataKeyframe(model, data, key)
    mujoco.mj_kinematics(model, data)
    return data


def task_parts(robot: RobotModel, model: mujoco.MjModel) -> TaskParts:
    """The IMU, feet and lowest point of ``robot`` (compiled as ``model``) from its spec's ``mjlab:``."""
    options, prefix = robot.spec.mjlab, robot.naming_prefix
    data = home_data(model)
    free = [j for j in range(model.njnt) if model.jnt_type[j] == mujoco.mjtJoint.mjJNT_FREE]
    root = model.body(int(model.jnt_bodyid[free[0]]) if free else 1).name
    imu_body = root if options.imu_body is None else _body(model, prefix, options.imu_body, "imu_body")
    field = "feet" if options.feet else "feet (the spec's)"
    feet_bodies = [_body(model, prefix, name, field) for name in options.feet or robot.spec.feet]
    collision = [g for g in range(model.ngeom) if _collides(model, g)]
    lowest = min((geom_lowest(model, data, g) for g in collision), default=0.0)
    lift = 0.0
    if free:
        zero = mujoco.MjData(model)  # qpos0: every joint at 0, the root at its body's position
        mujoco.mj_kinematics(model, zero)
        lift = -min((geom_lowest(model, zero, g) for g in collision), default=0.0)
    feet: list[tuple[str, str, tuple[float, float, float]]] = []
    geoms: list[str] = []
    problems: list[str] = []
    for body in feet_bodies:
        b = mujoco.mj_name2id(model, BODY, body)
        own = [g for g in collision if model.geom_bodyid[g] == b]
        if not own:
            problems.append(f"mjlab.feet: {body} has no collision geom to stand on")
            continue
        geoms += [mjlab_geom_name(model, g) for g in own]
        low = min(own, key=lambda g: geom_lowest(model, data, g))
        point = data.geom_xpos[low].copy()
        point[2] = geom_lowest(model, data, low)
        local = data.xmat[b].reshape(3, 3).T @ (point - data.xpos[b])
        feet.append((body, f"{body}_sole", (float(local[0]), float(local[1]), float(local[2]))))
    if problems:
        raise AssemblerError([Problem(p) for p in problems])
    return TaskParts(
        root=root,
        imu_body=imu_body,
        imu_site=prefix + "imu",
        imu_pos=options.imu_pos,
        feet=tuple(feet),
        foot_geoms=tuple(geoms),
        lowest=lowest,
        lift=lift,
    )
