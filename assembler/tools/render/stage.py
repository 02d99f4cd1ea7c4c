"""The scene a picture is taken in: a private copy of the assembly with a floor, lights and a sky.

Only the copy is edited (the robot's own MjSpec is never touched), so this is the one place
outside ``assembler/mjcf`` that adds elements to an MjSpec: they exist for the picture alone.
The copy is compiled once with the robot's ``home`` keyframe; the floor is then moved to the
robot's lowest point in the compiled model, which needs no second compile. Which geoms are drawn
is decided per part (:mod:`assembler.models.geom_groups`): its visual geoms, or its collision geoms when
it has none, unless the user chose the groups; the others are moved to a group that is not drawn.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.compiler.compile import compile_home
from assembler.compiler.keyframe import HOME_KEY
from assembler.mjcf import VISUAL_GROUPS
from assembler.models import PartModel, RobotModel
from assembler.models.geom_groups import PartGeoms, describe, geoms_by_part
from assembler.tools.render.backend import RenderError

FLOOR = "render_floor"
"""Name of the floor geom (and of its texture and material)."""

HIDDEN_GROUP = 3
"""Geom group not drawn by default (mjvOption shows groups 0-2): where undrawn geoms are moved."""

SHOWN_GROUP = 1
"""Where the geoms a picture shows are moved (whatever group they were in)."""

DRAWN_GROUPS = (0, 1, 2)


@dataclass(frozen=True)
class Stage:
    """The compiled picture scene at the home pose, and the points the camera has to frame."""

    model: mujoco.MjModel
    data: mujoco.MjData
    points: NDArray[np.float64]
    """Corners of the bounding box of every drawn robot geom, in world coordinates, shape (n, 3)."""

    shown: str = ""
    """Which geom groups are drawn, e.g. ``geom groups 1, 2`` (for the ``wrote ...`` line)."""

    @property
    def floor(self) -> int:
        """The floor's geom id."""
        return int(self.model.geom(FLOOR).id)


def _add_scenery(spec: mujoco.MjSpec) -> None:
    """A checkered floor, a gradient sky, a key light and a fill light (and a softer headlight).

    No shadows: MuJoCo's directional shadow maps speckle a floor this large ("shadow acne"), and a
    reviewer needs the geometry more than the shadow.
    """
    spec.add_texture(
        name=f"{FLOOR}_sky",
        type=mujoco.mjtTexture.mjTEXTURE_SKYBOX,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_GRADIENT,
        rgb1=[0.93, 0.95, 0.98],
        rgb2=[0.62, 0.68, 0.78],
        width=256,
        height=1536,
    )
    spec.add_texture(
        name=FLOOR,
        type=mujoco.mjtTexture.mjTEXTURE_2D,
        builtin=mujoco.mjtBuiltin.mjBUILTIN_CHECKER,
        rgb1=[0.82, 0.84, 0.86],
        rgb2=[0.70, 0.72, 0.75],
        width=256,
        height=256,
    )
    material = spec.add_material(name=FLOOR, texuniform=True, texrepeat=[4.0, 4.0], specular=0.0)
    material.textures[mujoco.mjtTextureRole.mjTEXROLE_RGB] = FLOOR
    floor = spec.worldbody.add_geom(name=FLOOR, type=mujoco.mjtGeom.mjGEOM_PLANE, material=FLOOR)
    floor.size = [1.0, 1.0, 0.05]  # resized to the robot after compiling
    floor.contype = floor.conaffinity = 0
    floor.group = DRAWN_GROUPS[-1]  # drawn whatever groups the robot's geoms are shown in
    spec.visual.headlight.ambient = [0.25] * 3
    spec.visual.headlight.diffuse = [0.3] * 3
    for direction, diffuse in (((-0.4, 0.3, -1.0), 0.5), ((0.5, -0.6, -0.6), 0.2)):
        light = spec.worldbody.add_light(pos=[0.0, 0.0, 3.0], dir=list(direction), castshadow=False)
        light.type = mujoco.mjtLightType.mjLIGHT_DIRECTIONAL
        light.diffuse = [diffuse] * 3
        light.specular = [0.1] * 3


def _drawn(model: mujoco.MjModel, parts: Sequence[PartGeoms], groups: Sequence[int] | None) -> set[int]:
    """The geoms to draw: those in ``groups``, else per part what it has (visual, else collision)."""
    if groups is not None:
        return {geom for geom in range(model.ngeom) if model.geom_group[geom] in groups}
    owned = {geom for part in parts for geom in part.geoms}
    drawn = {geom for part in parts for geom in part.geoms if model.geom_group[geom] in part.seen()}
    unowned = (geom for geom in range(model.ngeom) if geom not in owned)
    return drawn | {geom for geom in unowned if model.geom_group[geom] in VISUAL_GROUPS}


def _show_only(model: mujoco.MjModel, drawn: set[int], floor: int) -> None:
    """Move the drawn geoms to a drawn group and the others to a hidden one (this model is the picture's)."""
    for geom in range(model.ngeom):
        if geom != floor:
            model.geom_group[geom] = SHOWN_GROUP if geom in drawn else HIDDEN_GROUP


def _nothing_to_draw(robot: PartModel, parts: Sequence[PartGeoms], shown: str) -> RenderError:
    groups = sorted({group for part in parts for group in part.groups})
    having = f"its geoms are in {describe([], groups)}" if groups else "it has no geoms"
    return RenderError(
        f"nothing to draw: {type(robot).__name__} has no geom in {shown} ({having}); "
        "choose the groups to draw with --groups, e.g. --groups 0,1,2"
    )


def drawn_geoms(model: mujoco.MjModel) -> list[int]:
    """The geoms a picture shows (drawn groups, not transparent), except planes such as the floor."""
    return [
        geom
        for geom in range(model.ngeom)
        if model.geom_group[geom] in DRAWN_GROUPS
        and model.geom_rgba[geom, 3] > 0
        and model.geom_type[geom] != mujoco.mjtGeom.mjGEOM_PLANE
    ]


def box_corners(model: mujoco.MjModel, data: mujoco.MjData, geoms: list[int]) -> NDArray[np.float64]:
    """World coordinates of the 8 corners of each geom's bounding box (``geom_aabb``, in the geom frame)."""
    signs = np.array([[sx, sy, sz] for sx in (-1, 1) for sy in (-1, 1) for sz in (-1, 1)], dtype=float)
    corners = []
    for geom in geoms:
        center, half = model.geom_aabb[geom, :3], model.geom_aabb[geom, 3:]
        local = center + signs * half
        rotation = data.geom_xmat[geom].reshape(3, 3)
        corners.append(data.geom_xpos[geom] + local @ rotation.T)
    return np.concatenate(corners) if corners else np.zeros((1, 3))


def _assembly(part: PartModel) -> tuple[mujoco.MjSpec, dict[str, float], tuple[PartModel, ...]]:
    """A fresh assembly of ``part`` (a robot with its base and grippers; a gripper or base alone, as
    ``assembler build`` builds it), its home pose, and the parts whose geoms it holds."""
    if isinstance(part, RobotModel):
        return part.mjspec.copy(), part.assembly_home(), (part, *part.models)
    _, alone = part.compile_alone_spec()  # a new assembly each time: the picture's to edit
    return alone, part.home_qpos(), (part,)


def build_stage(robot: PartModel, width: int, height: int, groups: Sequence[int] | None = None) -> Stage:
    """Compile the robot (or a gripper or base alone) with scenery at its home pose, the floor just
    under its lowest point, showing the geoms in ``groups`` (default: each part's visual geoms, or its
    collision geoms if it has none)."""
    spec, home, members = _assembly(robot)
    spec.visual.global_.offwidth = max(width, spec.visual.global_.offwidth)
    spec.visual.global_.offheight = max(height, spec.visual.global_.offheight)
    _add_scenery(spec)
    model = compile_home(spec, home, f"{robot.family} '{type(robot).__name__}'")
    floor = model.geom(FLOOR).id
    parts = geoms_by_part(model, members)
    shown = describe(parts, groups)
    _show_only(model, _drawn(model, parts, groups), floor)
    if not drawn_geoms(model):  # an empty picture would say nothing, not even why
        raise _nothing_to_draw(robot, parts, shown)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, model.key(HOME_KEY).id)
    mujoco.mj_forward(model, data)
    points = box_corners(model, data, drawn_geoms(model))
    low, high = points.min(axis=0), points.max(axis=0)
    reach = float(np.max(high - low)) or 1.0
    model.geom_pos[floor] = [(low[0] + high[0]) / 2, (low[1] + high[1]) / 2, low[2] - 1e-3 * reach]
    model.geom_size[floor, :2] = 3.0 * reach
    model.mat_texrepeat[model.material(FLOOR).id] = 4.0 / reach  # about 8 squares across the robot
    data.geom_xpos[floor] = model.geom_pos[floor]  # mj_forward never recomputes static world geoms
    return Stage(model=model, data=data, points=points, shown=shown)
