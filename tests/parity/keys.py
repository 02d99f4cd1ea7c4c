"""Pair the elements of two compiled models: by name, and an unnamed element by its parent and its
order among the unnamed siblings of its kind (``robot0_link1/geom[2]``), never by a global index,
which shifts on one side when the other has an extra body.

robosuite names every unnamed geom of a part ``g{n}_col`` / ``g{n}_vis`` in document order
(models/base.py:515-523); we leave them unnamed, so on robosuite's side those names count as none.
"""

from __future__ import annotations

import re
from collections import defaultdict
from collections.abc import Mapping
from dataclasses import dataclass, field

import mujoco

WORLD = "world"
INVENTED_GEOM_NAME = re.compile(r"(^|_)g\d+_(col|vis)$")
"""A geom name robosuite made up for an unnamed geom (the prefix of the part stands before it)."""

OBJ = mujoco.mjtObj
KINDS: dict[str, tuple[mujoco.mjtObj, str]] = {
    "joint": (OBJ.mjOBJ_JOINT, "njnt"),
    "geom": (OBJ.mjOBJ_GEOM, "ngeom"),
    "site": (OBJ.mjOBJ_SITE, "nsite"),
    "camera": (OBJ.mjOBJ_CAMERA, "ncam"),
    "light": (OBJ.mjOBJ_LIGHT, "nlight"),
    "actuator": (OBJ.mjOBJ_ACTUATOR, "nu"),
    "sensor": (OBJ.mjOBJ_SENSOR, "nsensor"),
    "tendon": (OBJ.mjOBJ_TENDON, "ntendon"),
    "equality": (OBJ.mjOBJ_EQUALITY, "neq"),
    "key": (OBJ.mjOBJ_KEY, "nkey"),
    "mesh": (OBJ.mjOBJ_MESH, "nmesh"),
    "material": (OBJ.mjOBJ_MATERIAL, "nmat"),
    "texture": (OBJ.mjOBJ_TEXTURE, "ntex"),
}
"""Element kind -> (MuJoCo object type, count field)."""

PARENT_FIELD = {"joint": "jnt_bodyid", "geom": "geom_bodyid", "site": "site_bodyid"}
PARENT_FIELD |= {"camera": "cam_bodyid", "light": "light_bodyid"}


@dataclass
class Keys:
    """The pairing key of every element of one model, by kind, indexed like the model's arrays.

    A body that the other model does not have (``extra``) has key None; its children and elements
    count as its parent's (``effective_parent``).
    """

    body: list[str | None]
    effective_parent: list[int]
    kinds: dict[str, list[str]] = field(default_factory=dict)

    def of(self, kind: str, index: int) -> str:
        """The key of element ``index`` of ``kind`` (a body's effective key for bodies)."""
        if kind == "body":
            return self.body_key(index)
        return self.kinds[kind][index] if index >= 0 else "-"

    def body_key(self, body: int) -> str:
        key = self.body[self.effective_parent[body]] if self.body[body] is None else self.body[body]
        assert key is not None
        return key


def _name(model: mujoco.MjModel, obj: mujoco.mjtObj, index: int) -> str:
    return mujoco.mj_id2name(model, obj, index) or ""


def model_keys(
    model: mujoco.MjModel, renamed: Mapping[str, str] | None = None, extra: frozenset[str] = frozenset()
) -> Keys:
    """Keys of every element. ``renamed`` maps a body name to the name the other side uses; bodies
    named in ``extra`` are not on the other side."""
    renamed = renamed or {}
    bodies: list[str | None] = [WORLD]
    effective = [0]
    unnamed: defaultdict[tuple[str, str], int] = defaultdict(int)

    def unnamed_key(kind: str, parent: str) -> str:
        order = unnamed[(kind, parent)]
        unnamed[(kind, parent)] += 1
        return f"{parent}/{kind}[{order}]"

    for body in range(1, model.nbody):  # parents come before their children
        parent = model.body_parentid[body]
        parent_key = bodies[effective[parent]]
        assert parent_key is not None
        name = _name(model, OBJ.mjOBJ_BODY, body)
        if name in extra:
            bodies.append(None)
            effective.append(effective[parent])
            continue
        bodies.append(renamed.get(name, name) or unnamed_key("body", parent_key))
        effective.append(body)
    keys = Keys(bodies, effective)
    for kind, (obj, count) in KINDS.items():
        parents = getattr(model, PARENT_FIELD[kind]) if kind in PARENT_FIELD else None
        names = []
        for index in range(getattr(model, count)):
            name = _name(model, obj, index)
            if kind == "geom" and INVENTED_GEOM_NAME.search(name):
                name = ""
            parent = keys.body_key(parents[index]) if parents is not None else ""
            names.append(name or unnamed_key(kind, parent).lstrip("/"))
        keys.kinds[kind] = names
    return keys
