"""``assembler render``: a PNG of the assembled robot in its home pose, for reviewers."""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from assembler.cli.common import assembled
from assembler.files.paths import display_path
from assembler.files.writing import write_atomically
from assembler.tools.render import encode_png, take_picture
from assembler.tools.render.picture import check_views


def run(args: argparse.Namespace) -> int:
    views = [view.strip() for view in args.views.split(",") if view.strip()]
    check_views(views)  # before the robot is built: a typo should fail fast
    width, height = args.size
    picture = take_picture(assembled(args), views, width, height, args.labels, args.groups)
    target = Path(args.output)
    write_atomically(target, encode_png(picture.image))
    height, width, _ = picture.image.shape
    print(
        f"wrote {display_path(target)} ({width}x{height}, {', '.join(views)}; {picture.shown})",
        file=sys.stderr,
    )
    return 0
