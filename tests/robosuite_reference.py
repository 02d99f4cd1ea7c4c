"""robosuite as the oracle: assemble a robot the way ``robosuite.robots.Robot.load_model`` does,
and compare two compiled models field by field (names, tree, poses, joints, actuators, geoms,
inertia) with a relative tolerance. The parity tests use it; it needs robosuite installed.
"""

from __future__ import annotations

from typing import Any

import mujoco
import numpy as np

TOLERANCE = 1e-6
"""Relative tolerance of every numeric comparison (the parity issue's figure)."""


def robosuite_xml(
    robot: str, base: str | None = "default", grippers: dict[str, str | None] | None = None, idn: int = 0
) -> str:
    """robosuite's MJCF text: default base, default gripper per arm with the robot's gripper mount
    offsets, as ``Robot.load_model`` assembles it (robots/robot.py:161-223)."""
    return str(robosuite_robot_model(robot, base, grippers, idn).get_xml())


def robosuite_robot_model(
    robot: str, base: str | None = "default", grippers: dict[str, str | None] | None = None, idn: int = 0
) -> Any:
    """robosuite's robot model object of :func:`robosuite_xml`'s assembly (its ``get_xml`` not called)."""
    from robosuite.models.bases import robot_base_factory
    from robosuite.models.grippers import gripper_factory
    from robosuite.models.robots import create_robot
    from robosuite.utils.mjcf_utils import array_to_string

    model = create_robot(robot, idn=idn)
    base_name = model.default_base if base == "default" else base
    if base_name is not None:
        model.add_base(robot_base_factory(base_name, idn=idn))
    for arm in model.arms:
        name = (grippers or {}).get(arm, model.default_gripper[arm])
        gripper = gripper_factory(name, idn=f"{idn}_{arm}")
        root = gripper.worldbody.find("body")
        if arm in model.gripper_mount_pos_offset:
            root.set("pos", array_to_string(model.gripper_mount_pos_offset[arm]))
        if arm in model.gripper_mount_quat_offset:
            root.set("quat", array_to_string(model.gripper_mount_quat_offset[arm]))
        model.add_gripper(gripper, model.eef_name[arm])
    return model


def robosuite_model(
    robot: str, base: str | None = "default", grippers: dict[str, str | None] | None = None, idn: int = 0
) -> mujoco.MjModel:
    """robosuite's compiled model of the same assembly as :func:`robosuite_xml`."""
    return mujoco.MjModel.from_xml_string(robosuite_xml(robot, base, grippers, idn))


def _names(model: mujoco.MjModel, kind: mujoco.mjtObj, count: int) -> list[str]:
    return [mujoco.mj_id2name(model, kind, i) or f"#{i}" for i in range(count)]


def _close(a: np.ndarray, b: np.ndarray) -> bool:
    return a.shape == b.shape and bool(np.allclose(a, b, rtol=TOLERANCE, atol=TOLERANCE * 1e-3))


def differences(
    ours: mujoco.MjModel, reference: mujoco.MjModel, renamed: dict[str, str | None] | None = None
) -> list[str]:
    """Every way ``ours`` differs from ``reference``, one readable line each (empty: equal).

    ``renamed`` maps our body names to robosuite's for bodies we name differently on purpose, or to
    None for a body robosuite does not have (its children are then compared as children of its
    parent). Each entry that applies is reported as one difference; the rest is compared as usual.
    """
    found: list[str] = []
    for size in ("nq", "nv", "nu", "nbody", "njnt", "ngeom", "nsite", "ncam"):
        if getattr(ours, size) != getattr(reference, size):
            found.append(f"{size}: {getattr(ours, size)} != {getattr(reference, size)}")

    bodies = _names(ours, mujoco.mjtObj.mjOBJ_BODY, ours.nbody)
    extra: set[int] = set()
    for name, reference_name in (renamed or {}).items():
        if name not in bodies:
            continue
        if reference_name is None:
            extra.add(bodies.index(name))
            found.append(f"body {name}: not in robosuite")
        else:
            bodies[bodies.index(name)] = reference_name
            found.append(f"body {name}: named {reference_name} in robosuite")
    if extra:
        found = [line for line in found if not line.startswith("nbody:")]
    reference_bodies = _names(reference, mujoco.mjtObj.mjOBJ_BODY, reference.nbody)
    if {b for i, b in enumerate(bodies) if i not in extra} != set(reference_bodies):
        found.append(f"bodies only ours: {sorted(set(bodies) - set(reference_bodies))}")
        found.append(f"bodies only robosuite: {sorted(set(reference_bodies) - set(bodies))}")
        return found

    if len(set(bodies)) != len(bodies):
        found.append("bodies: unnamed bodies in different places, cannot pair them")
        return found
    reference_ids = {name: i for i, name in enumerate(reference_bodies)}

    def parent(model: mujoco.MjModel, names: list[str], body: int) -> str:
        body = model.body_parentid[body]
        while model is ours and body in extra:
            body = model.body_parentid[body]
        return names[body]

    ours_data, reference_data = mujoco.MjData(ours), mujoco.MjData(reference)
    for model, data in ((ours, ours_data), (reference, reference_data)):
        mujoco.mj_kinematics(model, data)
        mujoco.mj_camlight(model, data)
    # Unnamed bodies ("#13") pair by their index among the bodies; both sides keep them unnamed.
    for i, name in enumerate(bodies[1:], start=1):
        if i in extra:
            continue
        j = reference_ids[name]
        a, b = ours.body(i), reference.body(j)
        if parent(ours, bodies, i) != parent(reference, reference_bodies, j):
            found.append(
                f"body {name}: parent {parent(ours, bodies, i)} != {parent(reference, reference_bodies, j)}"
            )
        for field in ("mass", "inertia", "ipos"):
            if not _close(getattr(a, field), getattr(b, field)):
                found.append(f"body {name}: {field} {getattr(a, field)} != {getattr(b, field)}")
        if not _close(ours_data.xpos[i], reference_data.xpos[j]):
            found.append(f"body {name}: world position differs")
        if not _close(ours_data.xmat[i], reference_data.xmat[j]):
            found.append(f"body {name}: world orientation differs")
        geoms = _body_geoms(ours, i)
        reference_geoms = _body_geoms(reference, j)
        if geoms != reference_geoms:
            found.append(f"body {name}: geoms differ ({len(geoms)} vs {len(reference_geoms)})")

    for name in _names(reference, mujoco.mjtObj.mjOBJ_CAMERA, reference.ncam):
        if mujoco.mj_name2id(ours, mujoco.mjtObj.mjOBJ_CAMERA, name) < 0:
            found.append(f"camera {name}: missing")
        elif not _close(ours_data.cam(name).xpos, reference_data.cam(name).xpos):
            found.append(f"camera {name}: world position differs")

    for name in _names(reference, mujoco.mjtObj.mjOBJ_SITE, reference.nsite):
        if mujoco.mj_name2id(ours, mujoco.mjtObj.mjOBJ_SITE, name) < 0:
            found.append(f"site {name}: missing")
        elif not _close(ours_data.site(name).xpos, reference_data.site(name).xpos):
            found.append(f"site {name}: world position differs")

    found += _named_fields(ours, reference, "joint", JOINT_FIELDS)
    found += _named_fields(ours, reference, "actuator", ACTUATOR_FIELDS)
    return found


JOINT_FIELDS = ("type", "axis", "range", "armature", "damping", "frictionloss", "limited")
ACTUATOR_FIELDS = ("trntype", "trnid", "gear", "ctrlrange", "forcerange", "gainprm", "biasprm", "ctrllimited")
_KINDS = {"joint": (mujoco.mjtObj.mjOBJ_JOINT, "njnt"), "actuator": (mujoco.mjtObj.mjOBJ_ACTUATOR, "nu")}


def _named_fields(
    ours: mujoco.MjModel, reference: mujoco.MjModel, kind: str, fields: tuple[str, ...]
) -> list[str]:
    """Same names in the same order, then each field of each element within tolerance."""
    obj, count = _KINDS[kind]
    names = _names(ours, obj, getattr(ours, count))
    if names != _names(reference, obj, getattr(reference, count)):
        return [f"{kind} names or order differ"]
    found = []
    for index, name in enumerate(names):  # by index: an unnamed free joint is "#0" on both sides
        a, b = getattr(ours, kind)(index), getattr(reference, kind)(index)
        for field in fields:
            if not _close(np.asarray(getattr(a, field), float), np.asarray(getattr(b, field), float)):
                found.append(f"{kind} {name}: {field} {getattr(a, field)} != {getattr(b, field)}")
    return found


def _body_geoms(model: mujoco.MjModel, body: int) -> list[tuple[float, ...]]:
    """The body's geoms as comparable tuples (type, size, pos, contype, conaffinity, group, rgba)."""
    rows = []
    for geom in np.flatnonzero(model.geom_bodyid == body):
        rows.append(
            tuple(
                np.round(
                    np.concatenate(
                        [
                            [model.geom_type[geom]],
                            model.geom_size[geom],
                            model.geom_pos[geom],
                            [model.geom_contype[geom], model.geom_conaffinity[geom], model.geom_group[geom]],
                            model.geom_rgba[geom],
                        ]
                    ),
                    9,
                )
            )
        )
    return sorted(rows)
