"""What is compared of each element, family by family. A field's value is numbers (compared within
the tolerance) or text (compared exactly: types, and the keys of referenced elements, never their
indices). Poses are compared in the world frame at qpos0, so a body that one side splits in two
still pairs; everything else in the element's own frame.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import mujoco
import numpy as np

from tests.parity.keys import Keys

Fields = dict[str, Any]
Extractor = Callable[[mujoco.MjModel, mujoco.MjData, Keys, int], Fields]

_OBJ_KIND = {
    mujoco.mjtObj.mjOBJ_BODY: "body",
    mujoco.mjtObj.mjOBJ_XBODY: "body",
    mujoco.mjtObj.mjOBJ_JOINT: "joint",
    mujoco.mjtObj.mjOBJ_GEOM: "geom",
    mujoco.mjtObj.mjOBJ_SITE: "site",
    mujoco.mjtObj.mjOBJ_CAMERA: "camera",
    mujoco.mjtObj.mjOBJ_TENDON: "tendon",
    mujoco.mjtObj.mjOBJ_ACTUATOR: "actuator",
}


def ref(keys: Keys, obj: int, index: int) -> str:
    """A referenced element as ``kind key`` (``-`` for none)."""
    kind = _OBJ_KIND.get(mujoco.mjtObj(obj))
    if kind is None or index < 0:
        return f"{mujoco.mjtObj(obj).name} {index}" if index >= 0 else "-"
    return f"{kind} {keys.of(kind, index)}"


def _optional(model: mujoco.MjModel, i: int, **fields: tuple[str, ...]) -> Fields:
    """Fields whose array is named differently, or exists only, in some MuJoCo versions."""
    found = {}
    for label, names in fields.items():
        for name in names:
            if hasattr(model, name):
                found[label] = getattr(model, name)[i]
                break
    return found


def _dofs(model: mujoco.MjModel, joint: int) -> slice:
    start = model.jnt_dofadr[joint]
    count = {0: 6, 1: 3}.get(int(model.jnt_type[joint]), 1)
    return slice(start, start + count)


def _qpos(model: mujoco.MjModel, joint: int) -> slice:
    start = model.jnt_qposadr[joint]
    return slice(start, start + {0: 7, 1: 4}.get(int(model.jnt_type[joint]), 1))


def body(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    rotation = data.ximat[i].reshape(3, 3)
    return {
        "parent": keys.body_key(model.body_parentid[i]),
        "mass": model.body_mass[i],
        "inertia": rotation @ np.diag(model.body_inertia[i]) @ rotation.T,  # in world axes
        "inertial frame": data.xipos[i],
        "world position": data.xpos[i],
        "world orientation": data.xmat[i],
        "gravcomp": model.body_gravcomp[i],
    }


def joint(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    dofs = _dofs(model, i)
    return {
        "body": keys.body_key(model.jnt_bodyid[i]),
        "type": mujoco.mjtJoint(model.jnt_type[i]).name,
        "axis": model.jnt_axis[i],  # in the joint's body frame: bodies pair, their poses compare
        "anchor": model.jnt_pos[i],
        "range": model.jnt_range[i],
        "limited": model.jnt_limited[i],
        "stiffness": model.jnt_stiffness[i],
        "springref": model.qpos_spring[_qpos(model, i)],
        "qpos0": model.qpos0[_qpos(model, i)],
        "solref": model.jnt_solref[i],
        "solimp": model.jnt_solimp[i],
        "margin": model.jnt_margin[i],
        "armature": model.dof_armature[dofs],
        "damping": model.dof_damping[dofs],
        "frictionloss": model.dof_frictionloss[dofs],
        "friction solref": model.dof_solref[dofs],
        "friction solimp": model.dof_solimp[dofs],
        "actfrcrange": model.jnt_actfrcrange[i],
        "actfrclimited": model.jnt_actfrclimited[i],
        "group": model.jnt_group[i],
    } | _optional(model, i, **{"stiffness polynomial": ("jnt_stiffnesspoly",)})


def _asset(model: mujoco.MjModel, keys: Keys, kind: str, index: int) -> str:
    return keys.of(kind, index) if index >= 0 else "-"


def geom(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    is_mesh = int(model.geom_type[i]) in (int(mujoco.mjtGeom.mjGEOM_MESH), int(mujoco.mjtGeom.mjGEOM_SDF))
    return {
        "body": keys.body_key(model.geom_bodyid[i]),
        "type": mujoco.mjtGeom(model.geom_type[i]).name,
        "size": model.geom_size[i],
        "world position": data.geom_xpos[i],
        "world orientation": data.geom_xmat[i],
        "friction": model.geom_friction[i],
        "solref": model.geom_solref[i],
        "solimp": model.geom_solimp[i],
        "solmix": model.geom_solmix[i],
        "condim": model.geom_condim[i],
        "priority": model.geom_priority[i],
        "margin": model.geom_margin[i],
        "gap": model.geom_gap[i],
        "contype": model.geom_contype[i],
        "conaffinity": model.geom_conaffinity[i],
        "group": model.geom_group[i],
        "rgba": model.geom_rgba[i],
        "mesh": _asset(model, keys, "mesh", model.geom_dataid[i] if is_mesh else -1),
        "material": _asset(model, keys, "material", model.geom_matid[i]),
    }


def site(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    return {
        "body": keys.body_key(model.site_bodyid[i]),
        "type": mujoco.mjtGeom(model.site_type[i]).name,
        "size": model.site_size[i],
        "world position": data.site_xpos[i],
        "world orientation": data.site_xmat[i],
        "rgba": model.site_rgba[i],
        "group": model.site_group[i],
    }


def camera(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    return {
        "body": keys.body_key(model.cam_bodyid[i]),
        "mode": mujoco.mjtCamLight(model.cam_mode[i]).name,
        "target": keys.body_key(model.cam_targetbodyid[i]) if model.cam_targetbodyid[i] >= 0 else "-",
        "world position": data.cam_xpos[i],
        "world orientation": data.cam_xmat[i],
        "fovy": model.cam_fovy[i],
        "ipd": model.cam_ipd[i],
        "resolution": model.cam_resolution[i],
    } | _optional(model, i, projection=("cam_projection", "cam_orthographic"))


def light(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    return {
        "body": keys.body_key(model.light_bodyid[i]),
        "mode": mujoco.mjtCamLight(model.light_mode[i]).name,
        "world position": data.light_xpos[i],
        "world direction": data.light_xdir[i],
        "castshadow": model.light_castshadow[i],
        "active": model.light_active[i],
        "diffuse": model.light_diffuse[i],
        "ambient": model.light_ambient[i],
        "specular": model.light_specular[i],
        "attenuation": model.light_attenuation[i],
        "cutoff": model.light_cutoff[i],
        "exponent": model.light_exponent[i],
    } | _optional(model, i, type=("light_type", "light_directional"))


def actuator(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    transmission = mujoco.mjtTrn(model.actuator_trntype[i])
    target_kind = {0: "joint", 1: "joint", 2: "site", 3: "tendon", 4: "site", 5: "body"}[int(transmission)]
    targets = [keys.of(target_kind, t) if t >= 0 else "-" for t in model.actuator_trnid[i]]
    return {
        "transmission": f"{transmission.name} {' '.join(targets)}",
        "gear": model.actuator_gear[i],
        "dyntype": mujoco.mjtDyn(model.actuator_dyntype[i]).name,
        "gaintype": mujoco.mjtGain(model.actuator_gaintype[i]).name,
        "biastype": mujoco.mjtBias(model.actuator_biastype[i]).name,
        "dynprm": model.actuator_dynprm[i],
        "gainprm": model.actuator_gainprm[i],
        "biasprm": model.actuator_biasprm[i],
        "actearly": model.actuator_actearly[i],
        "ctrlrange": model.actuator_ctrlrange[i],
        "ctrllimited": model.actuator_ctrllimited[i],
        "forcerange": model.actuator_forcerange[i],
        "forcelimited": model.actuator_forcelimited[i],
        "actrange": model.actuator_actrange[i],
        "actlimited": model.actuator_actlimited[i],
        "actdim": model.actuator_actnum[i],
        "cranklength": model.actuator_cranklength[i],
        "lengthrange": model.actuator_lengthrange[i],
        "group": model.actuator_group[i],
    } | _optional(model, i, damping=("actuator_damping",), armature=("actuator_armature",))


def sensor(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    return {
        "type": mujoco.mjtSensor(model.sensor_type[i]).name,
        "object": ref(keys, model.sensor_objtype[i], model.sensor_objid[i]),
        "reference": ref(keys, model.sensor_reftype[i], model.sensor_refid[i]),
        "datatype": model.sensor_datatype[i],
        "needstage": model.sensor_needstage[i],
        "dim": model.sensor_dim[i],
        "cutoff": model.sensor_cutoff[i],
        "noise": model.sensor_noise[i],
    }


def tendon(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    start, count = model.tendon_adr[i], model.tendon_num[i]
    wraps = []
    for w in range(start, start + count):
        kind = {mujoco.mjtWrap.mjWRAP_JOINT: "joint", mujoco.mjtWrap.mjWRAP_SITE: "site"}.get(
            mujoco.mjtWrap(model.wrap_type[w]), "geom"
        )
        target = keys.of(kind, model.wrap_objid[w]) if model.wrap_objid[w] >= 0 else "-"
        wraps.append(f"{mujoco.mjtWrap(model.wrap_type[w]).name} {target} {model.wrap_prm[w]:.9g}")
    return {
        "path": "; ".join(wraps),
        "stiffness": model.tendon_stiffness[i],
        "damping": model.tendon_damping[i],
        "frictionloss": model.tendon_frictionloss[i],
        "armature": model.tendon_armature[i],
        "range": model.tendon_range[i],
        "limited": model.tendon_limited[i],
        "lengthspring": model.tendon_lengthspring[i],
        "solref": model.tendon_solref_lim[i],
        "solimp": model.tendon_solimp_lim[i],
        "friction solref": model.tendon_solref_fri[i],
        "friction solimp": model.tendon_solimp_fri[i],
        "margin": model.tendon_margin[i],
        "width": model.tendon_width[i],
        "rgba": model.tendon_rgba[i],
        "group": model.tendon_group[i],
    }


def equality(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    objtype = model.eq_objtype[i]
    return {
        "type": mujoco.mjtEq(model.eq_type[i]).name,
        "objects": f"{ref(keys, objtype, model.eq_obj1id[i])}, {ref(keys, objtype, model.eq_obj2id[i])}",
        "data": model.eq_data[i],
        "solref": model.eq_solref[i],
        "solimp": model.eq_solimp[i],
        "active": model.eq_active0[i],
    }


def mesh(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    vertices = slice(model.mesh_vertadr[i], model.mesh_vertadr[i] + model.mesh_vertnum[i])
    return {
        "vertices": model.mesh_vert[vertices],
        "faces": model.mesh_facenum[i],
        "scale": model.mesh_scale[i],
    }


def material(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    textures = [keys.of("texture", t) if t >= 0 else "-" for t in model.mat_texid[i]]
    return {
        "rgba": model.mat_rgba[i],
        "emission": model.mat_emission[i],
        "specular": model.mat_specular[i],
        "shininess": model.mat_shininess[i],
        "reflectance": model.mat_reflectance[i],
        "texrepeat": model.mat_texrepeat[i],
        "textures": " ".join(textures),
    }


def texture(model: mujoco.MjModel, data: mujoco.MjData, keys: Keys, i: int) -> Fields:
    return {
        "type": model.tex_type[i],
        "size": np.array([model.tex_width[i], model.tex_height[i], model.tex_nchannel[i]]),
    }


FAMILIES: dict[str, Extractor] = {
    "body": body,
    "joint": joint,
    "geom": geom,
    "site": site,
    "camera": camera,
    "light": light,
    "actuator": actuator,
    "sensor": sensor,
    "tendon": tendon,
    "equality": equality,
    "mesh": mesh,
    "material": material,
    "texture": texture,
}
"""Element families compared field by field, paired by key (keys.py)."""
