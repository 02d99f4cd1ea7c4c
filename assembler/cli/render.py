"""``assembler render``: a PNG of the assembled robot in its home pose, for reviewers."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.cli.common import add_assembly_arguments, assembled
from assembler.paths import display_path
from assembler.render import LABELS, VIEWS, encode_png, render_robot
from assembler.render.picture import check_views
from assembler.writing import write_atomically

MAX_SIDE = 8192
"""Largest view width or height accepted (MuJoCo allocates an offscreen buffer of that size)."""


def image_size(text: str) -> tuple[int, int]:
    """``--size WxH`` as (width, height)."""
    width, sep, height = text.lower().partition("x")
    if not (sep and width.isdigit() and height.isdigit()):
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, e.g. 640x480, got '{text}'")
    size = (int(width), int(height))
    if not all(1 <= side <= MAX_SIDE for side in size):
        raise argparse.ArgumentTypeError(f"each side must be 1 to {MAX_SIDE} pixels, got '{text}'")
    return size


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser(
        "render",
        help="write a PNG of the assembled robot in its home pose",
        description="Render the assembled robot in its home pose (keyframe 'home') with MuJoCo's "
        "offscreen renderer, auto-framed, on a floor, one tile per view.",
        epilog="Headless Linux: when MUJOCO_GL is unset and there is no DISPLAY, MUJOCO_GL=egl is "
        "used; set MUJOCO_GL=osmesa for software rendering.",
    )
    add_assembly_arguments(parser, cached=False)  # a picture compiles the spec it poses
    parser.add_argument("-o", "--output", required=True, help="PNG file to write")
    parser.add_argument(
        "--views",
        default="iso",
        help=f"comma-separated views, tiled in this order: {', '.join(VIEWS)} (default: iso)",
    )
    parser.add_argument(
        "--labels",
        nargs="?",
        const="joints",
        choices=sorted(LABELS),
        help="write element names next to them (default when given alone: joints)",
    )
    parser.add_argument(
        "--size",
        type=image_size,
        default=(640, 480),
        metavar="WxH",
        help="size of each view (default 640x480)",
    )
    parser.set_defaults(run=run)


def run(args: argparse.Namespace) -> int:
    views = [view.strip() for view in args.views.split(",") if view.strip()]
    check_views(views)  # before the robot is built: a typo should fail fast
    width, height = args.size
    image = render_robot(assembled(args), views, width, height, args.labels)
    target = Path(args.output)
    write_atomically(target, encode_png(image))
    print(
        f"wrote {display_path(target)} ({image.shape[1]}x{image.shape[0]}, {', '.join(views)})",
        file=sys.stderr,
    )
    return 0
