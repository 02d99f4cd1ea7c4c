"""Pictures of assembled robots: MuJoCo's offscreen renderer, auto-framing, PNG output (stdlib only).

``render_robot(robot, views)`` returns an RGB array; ``encode_png`` turns it into PNG bytes. The
scene (floor, lights) is added to a copy of the robot's MjSpec; the robot itself is not changed.
"""

from assembler.tools.render.backend import RenderError, choose_backend
from assembler.tools.render.framing import VIEWS
from assembler.tools.render.picture import LABELS, Picture, render_robot, take_picture
from assembler.tools.render.png import encode_png

__all__ = [
    "LABELS",
    "VIEWS",
    "Picture",
    "RenderError",
    "choose_backend",
    "encode_png",
    "render_robot",
    "take_picture",
]
