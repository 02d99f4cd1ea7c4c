"""A picture of an assembled robot: its home pose from one or more views, tiled into one image."""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.models import PartModel
from assembler.tools.render.backend import RenderError, new_renderer
from assembler.tools.render.framing import VIEWS, frame
from assembler.tools.render.stage import Stage, build_stage

LABELS: dict[str, mujoco.mjtLabel] = {
    "joints": mujoco.mjtLabel.mjLABEL_JOINT,
    "sites": mujoco.mjtLabel.mjLABEL_SITE,
    "bodies": mujoco.mjtLabel.mjLABEL_BODY,
}
"""``--labels`` choices -> what MuJoCo writes next to each element (``mjvOption.label``)."""

Image = NDArray[np.uint8]


def check_views(views: Sequence[str]) -> None:
    """Every view name is known; one :class:`RenderError` listing the valid names otherwise."""
    unknown = [view for view in views if view not in VIEWS]
    if unknown or not views:
        raise RenderError(
            f"unknown view(s): {', '.join(unknown) or '(none given)'}; choose from {', '.join(VIEWS)}"
        )


def scene_option(labels: str | None) -> mujoco.MjvOption:
    """Geoms as MuJoCo draws them by default; sites only when labelled (robosuite's grippers carry a
    10 m long eef-axis site); the labels asked for (joint labels need the joints drawn)."""
    option = mujoco.MjvOption()
    if labels != "sites":
        option.sitegroup[:] = 0
    if labels is not None:
        option.label = LABELS[labels]
        if labels == "joints":
            option.flags[mujoco.mjtVisFlag.mjVIS_JOINT] = True
    return option


def render_views(
    stage: Stage, views: Sequence[str], width: int, height: int, labels: str | None = None
) -> list[Image]:
    """One (height, width, 3) image per view of the staged robot."""
    check_views(views)
    option = scene_option(labels)
    fovy = float(stage.model.vis.global_.fovy)
    images: list[Image] = []
    renderer = new_renderer(stage.model, width, height)
    try:
        for view in views:
            camera = frame(stage.points, view, fovy, width / height).camera()
            renderer.update_scene(stage.data, camera=camera, scene_option=option)
            images.append(renderer.render().copy())
    finally:
        renderer.close()
    return images


def tile(images: Sequence[Image]) -> Image:
    """Images of one size side by side: up to three in a row, four as 2x2, more in rows of ceil(sqrt(n))."""
    count = len(images)
    columns = count if count <= 3 else math.ceil(math.sqrt(count))
    rows = math.ceil(count / columns)
    height, width, _ = images[0].shape
    sheet = np.full((rows * height, columns * width, 3), 255, dtype=np.uint8)
    for index, image in enumerate(images):
        row, column = divmod(index, columns)
        sheet[row * height : (row + 1) * height, column * width : (column + 1) * width] = image
    return sheet


@dataclass(frozen=True)
class Picture:
    """A rendered picture and which geom groups it shows."""

    image: Image
    shown: str
    """e.g. ``geom groups 1, 2``, or ``geom group 0 (collision) for Blocky: it has no visual geoms``."""


def take_picture(
    robot: PartModel,
    views: Sequence[str] = ("iso",),
    width: int = 640,
    height: int = 480,
    labels: str | None = None,
    groups: Sequence[int] | None = None,
) -> Picture:
    """The robot in its home pose with a floor and lights, each view auto-framed, tiled into one
    image; ``groups`` are the geom groups drawn (default: each part's visual geoms, or its collision
    geoms when it has no visual ones)."""
    check_views(views)
    stage = build_stage(robot, width, height, groups)
    return Picture(tile(render_views(stage, views, width, height, labels)), stage.shown)


def render_robot(
    robot: PartModel,
    views: Sequence[str] = ("iso",),
    width: int = 640,
    height: int = 480,
    labels: str | None = None,
    groups: Sequence[int] | None = None,
) -> Image:
    """:func:`take_picture`'s image."""
    return take_picture(robot, views, width, height, labels, groups).image
