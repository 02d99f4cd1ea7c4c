"""Which spec fields a compiled model can take without a compile, and the patch that applies them.

A variant that changes only parameters MuJoCo derives nothing structural from is the compiled
model of the robot with some array entries replaced, then its derived constants recomputed
(``mujoco.mj_setConst``). :data:`PATCHABLE` says which spec fields those are and which ``MjModel``
fields each one writes; :func:`model_patch` compares a variant with the robot it varies (their
resolved joint, actuator and ``bodies:``/``geoms:`` tables, not the override text) and returns
the entries to write, or raises :class:`NotPatchable` naming the field that needs a compile.
Anything else (counts, types, names, meshes, added or removed elements) is structural.
"""

from __future__ import annotations

import copy
from typing import Any

import mujoco
import numpy as np

from assembler.errors import AssemblerError
from assembler.mjcf.census import scaled_size
from assembler.models import RobotModel
from assembler.models.physical import ZONE_SENSORS
from assembler.patch.derived import ModelPatch, apply_patch
from assembler.patch.resolved import Resolved

PATCHABLE: dict[str, tuple[str, ...]] = {
    "joint_defaults.frictionloss, joints[i].frictionloss": ("dof_frictionloss",),
    "joint_defaults.damping, joints[i].damping": ("dof_damping",),
    "joint_defaults.armature, joints[i].armature": ("dof_armature",),
    "joints[i].stiffness": ("jnt_stiffness",),
    "actuators[i].kp, kv, dampratio, gainprm, biasprm": ("actuator_gainprm", "actuator_biasprm"),
    "actuators[i].gear": ("actuator_gear",),
    "motors[i].gear_ratio, efficiency (the joint values and actuator they give)": (
        "dof_armature",
        "dof_frictionloss",
        "dof_damping",
        "actuator_gainprm",
        "actuator_biasprm",
        "actuator_gear",
        "actuator_ctrlrange",
        "actuator_forcerange",
    ),
    "actuators[i].ctrlrange, forcerange (once set)": ("actuator_ctrlrange", "actuator_forcerange"),
    "bodies[i].mass_scale": ("body_mass", "body_inertia"),
    "bodies[i].size_scale (bodies without mesh geoms)": (
        "body_mass",
        "body_inertia",
        "body_ipos",
        "body_pos",
        "geom_size",
        "geom_pos",
        "geom_rbound",
        "geom_aabb",
        "site_pos",
        "site_size",
        "jnt_pos",
        "cam_pos",
        "light_pos",
        "bvh_aabb",
    ),
    "geoms[i].friction": ("geom_friction",),
    "init_qpos": ("key_qpos",),
}
"""Spec fields -> the ``MjModel`` fields a change of them writes (the home keyframe's row for init_qpos;
``site_size`` of a sensor's zone only)."""

DERIVED: tuple[str, ...] = (
    "key_ctrl",
    "body_subtreemass",
    "body_invweight0",
    "dof_invweight0",
    "dof_M0",
    "actuator_acc0",
    "actuator_length0",
    "cam_pos0",
    "cam_poscom0",
    "light_pos0",
    "light_poscom0",
)
"""Fields ``mj_setConst`` recomputes from the patched ones. Recomputed by :mod:`assembler.patch.derived`
as MuJoCo's compiler does: a dampratio's ``actuator_biasprm[2]``, the home keyframe's controls,
``stat.meaninertia`` and ``stat.meanmass``. Not recomputed: ``stat.extent``, ``stat.center`` and
``stat.meansize``, which only drawing reads (a size_scale leaves them at the compiled robot's values)."""

STRUCTURAL = (
    "counts (joints, actuators, bodies, geoms), element types, names, transmissions, mesh data "
    "(a size_scale of a body with mesh geoms), limits switched on or off, and every other spec field"
)
"""What a patch never changes: a variant that changes any of these is compiled."""

PATCHED_SECTIONS = frozenset(
    {"joint_defaults", "joints", "actuators", "motors", "bodies", "geoms", "init_qpos"}
)
"""Top-level spec fields whose effects :func:`model_patch` resolves; a change elsewhere is structural."""

ACTUATOR_VALUES: tuple[tuple[str, str], ...] = (
    ("gainprm", "actuator_gainprm"),
    ("biasprm", "actuator_biasprm"),
    ("gear", "actuator_gear"),
    ("ctrlrange", "actuator_ctrlrange"),
    ("forcerange", "actuator_forcerange"),
)
ACTUATOR_STRUCTURE: tuple[str, ...] = (
    "trntype",
    "dyntype",
    "gaintype",
    "biastype",
    "target",
    "ctrllimited",
    "forcelimited",
    "dynprm",
)
JOINT_FIELDS: dict[str, str] = {
    "frictionloss": "dof_frictionloss",
    "damping": "dof_damping",
    "armature": "dof_armature",
    "stiffness": "jnt_stiffness",
}


SCALED_WITH_BODY: tuple[tuple[str, mujoco.mjtObj, tuple[str, ...]], ...] = (
    ("body_parentid", mujoco.mjtObj.mjOBJ_BODY, ("body_pos",)),
    ("geom_bodyid", mujoco.mjtObj.mjOBJ_GEOM, ("geom_pos", "geom_size", "geom_rbound", "geom_aabb")),
    ("site_bodyid", mujoco.mjtObj.mjOBJ_SITE, ("site_pos", "site_size")),
    ("jnt_bodyid", mujoco.mjtObj.mjOBJ_JOINT, ("jnt_pos",)),
    ("cam_bodyid", mujoco.mjtObj.mjOBJ_CAMERA, ("cam_pos",)),
    ("light_bodyid", mujoco.mjtObj.mjOBJ_LIGHT, ("light_pos",)),
)
"""(owner field, element kind, fields scaled by S) for what a size_scale scales in the body's frame;
a site's size only when it is a sensor's zone (``assembler.models.physical``: the compile's rule)."""


def _zone_sites(model: mujoco.MjModel) -> set[int]:
    """The sites of ``model`` that are a sensor's zone (``assembler.models.physical.ZONE_SENSORS``)."""
    site = mujoco.mjtObj.mjOBJ_SITE
    zones = np.isin(model.sensor_type, list(ZONE_SENSORS))
    objects = model.sensor_objid[zones & (model.sensor_objtype == site)]
    references = model.sensor_refid[zones & (model.sensor_reftype == site)]
    return {int(i) for i in (*objects, *references)}


class NotPatchable(AssemblerError):
    """A variant changes something a compiled model cannot take: it must be compiled."""


def _structure_problem(base: Resolved, variant: Resolved) -> str | None:
    """The first top-level spec field outside :data:`PATCHED_SECTIONS` that differs, if any."""
    ours, theirs = base.dump, variant.dump
    for key in ours:
        if key not in PATCHED_SECTIONS and ours[key] != theirs[key]:
            return key
    if base.joint_names != variant.joint_names:
        return "joints (a different set of joints)"
    return None


def _joint_entries(patch: ModelPatch, model: mujoco.MjModel, base: Resolved, variant: Resolved) -> None:
    for name in variant.joint_names:
        joint = model.joint(variant.prefix + name)
        ndof = {0: 6, 1: 3}.get(int(joint.type[0]), 1)
        for attribute, target in JOINT_FIELDS.items():
            old, new = base.joint_values[name].get(attribute), variant.joint_values[name].get(attribute)
            if old == new or (old is not None and new is not None and old.value == new.value):
                continue
            value = 0.0 if new is None else new.value  # absent: neither the file nor the spec sets it
            if target == "jnt_stiffness":
                patch.set(target, int(joint.id), value)
            else:
                for dof in range(int(joint.dofadr[0]), int(joint.dofadr[0]) + ndof):
                    patch.set(target, dof, value)


def _actuator_entries(patch: ModelPatch, model: mujoco.MjModel, base: Resolved, variant: Resolved) -> None:
    if variant.actuators is base.actuators:  # resolved against the robot's own MJCF: only dampratios
        for actuator in variant.actuators:
            if actuator.biasprm[2] > 0:
                row = model.actuator(variant.prefix + actuator.name).id
                patch.dampratio[row] = float(actuator.biasprm[2])
                patch.set("actuator_biasprm", row, model.actuator_biasprm[row].copy())
        return
    ours = {a.name: a for a in base.actuators}
    theirs = {a.name: a for a in variant.actuators}
    if list(ours) != list(theirs):
        raise NotPatchable("actuators: the variant has other actuators (a count or names); compile it")
    for name, new in theirs.items():
        old = ours[name]
        for attribute in ACTUATOR_STRUCTURE:
            if not np.array_equal(np.asarray(getattr(old, attribute)), np.asarray(getattr(new, attribute))):
                raise NotPatchable(f"actuators: '{name}' changes its {attribute}, which is structural")
        row = model.actuator(variant.prefix + name).id
        for attribute, target in ACTUATOR_VALUES:
            value = np.array(getattr(new, attribute), dtype=float)  # a copy: the spec may be freed first
            changed = not np.array_equal(value, getattr(old, attribute))
            switched = not value.any() or not np.asarray(getattr(old, attribute)).any()
            if attribute.endswith("range") and changed and switched:
                raise NotPatchable(f"actuators: '{name}' {attribute} switches a limit on or off")
            if attribute == "biasprm" and value[2] > 0:  # a dampratio: MuJoCo's compiler resolves it
                patch.dampratio[row] = float(value[2])
            if not np.array_equal(value, getattr(old, attribute)) or row in patch.dampratio:
                patch.set(target, row, value[: getattr(model, target).shape[1]])


def _owned(model: mujoco.MjModel, kind: mujoco.mjtObj, index: int, prefix: str) -> bool:
    """True for an element of the robot's own part (its prefix, or unnamed), not a gripper's or base's."""
    name = mujoco.mj_id2name(model, kind, index) or ""
    return name == "" or name.startswith(prefix)


def _body_entries(patch: ModelPatch, model: mujoco.MjModel, base: Resolved, variant: Resolved) -> None:
    prefix = variant.prefix
    for name in {*base.physical.bodies, *variant.physical.bodies}:
        (s0, m0, i0), (s1, m1, i1) = base.physical.factors(name), variant.physical.factors(name)
        if (s0, m0, i0) == (s1, m1, i1):
            continue
        body = model.body(prefix + name).id
        size, mass, inertia = s1 / s0, m1 / m0, i1 / i0
        patch.set("body_mass", body, model.body_mass[body] * mass)
        patch.set("body_inertia", body, model.body_inertia[body] * inertia)
        if size == 1.0:
            continue
        patch.set("body_ipos", body, model.body_ipos[body] * size)
        first = model.body_bvhadr[body]
        for node in range(first, first + model.body_bvhnum[body]) if first >= 0 else ():
            patch.set("bvh_aabb", node, model.bvh_aabb[node] * size)  # the body's geoms' bounding boxes
        geoms = np.flatnonzero(model.geom_bodyid == body)
        if (model.geom_type[geoms] == mujoco.mjtGeom.mjGEOM_MESH).any():
            raise NotPatchable(
                f"bodies: size_scale of '{name}' scales its meshes (mesh data, not patchable); compile it"
            )
        zones = _zone_sites(model)
        for parent_field, kind, targets in SCALED_WITH_BODY:
            for element in np.flatnonzero(getattr(model, parent_field) == body):
                if kind == mujoco.mjtObj.mjOBJ_BODY and element == body:
                    continue  # the world body is its own parent
                if _owned(model, kind, int(element), prefix):
                    for target in targets:
                        if target != "site_size" or int(element) in zones:
                            patch.set(target, int(element), _scaled(model, target, int(element), size))
    for name in {*base.physical.geoms, *variant.physical.geoms}:
        old, new = base.physical.geoms.get(name), variant.physical.geoms.get(name)
        if new is None:
            raise NotPatchable(f"geoms: '{name}' goes back to the file's friction; compile it")
        if old is None or old.value != new.value:
            patch.set("geom_friction", model.geom(prefix + name).id, np.asarray(new.value, dtype=float))


def _scaled(model: mujoco.MjModel, target: str, element: int, size: float) -> Any:
    """A row of ``target`` scaled by a body's size_scale: of a geom's or site's size, the numbers
    its type reads (as the compile scales it: :mod:`assembler.mjcf.census`)."""
    row = getattr(model, target)[element]
    if target in ("geom_size", "site_size"):
        kind = model.geom_type[element] if target == "geom_size" else model.site_type[element]
        return scaled_size(row, int(kind), size)
    return row * size


def _home_entries(patch: ModelPatch, model: mujoco.MjModel, base: Resolved, variant: Resolved) -> None:
    if base.spec.init_qpos == variant.spec.init_qpos:
        return
    home = model.key("home").id
    qpos = model.key_qpos[home].copy()
    for index, joint in enumerate(variant.joint_names):
        address = model.jnt_qposadr[model.joint(variant.prefix + joint).id]
        given = variant.spec.init_qpos
        qpos[address] = given[index] if given is not None else model.qpos0[address]
    patch.set("key_qpos", home, qpos)


def model_patch(model: mujoco.MjModel, base: Resolved, variant: Resolved) -> ModelPatch:
    """What turns ``model`` (the compiled ``base``) into the compiled ``variant``; :class:`NotPatchable`
    names the first change that needs a compile."""
    different = _structure_problem(base, variant)
    if different is not None:
        raise NotPatchable(
            f"{different}: not a patchable field ({', '.join(PATCHABLE)}); compile the variant"
        )
    patch = ModelPatch()
    _joint_entries(patch, model, base, variant)
    _actuator_entries(patch, model, base, variant)
    _body_entries(patch, model, base, variant)
    _home_entries(patch, model, base, variant)
    return patch


def patched_model(model: mujoco.MjModel, base: RobotModel, variant: RobotModel) -> mujoco.MjModel:
    """A copy of ``model`` (the compiled ``base``) patched into the compiled ``variant``."""
    patch = model_patch(model, Resolved.of(base), Resolved.of(variant))
    patched = copy.copy(model)  # MuJoCo's mj_copyModel: its own arrays
    apply_patch(patched, patch)
    return patched
