"""MuJoCo's naming rule for unnamed file-backed assets, applied before anything replaces their files.

An unnamed ``<mesh file="base_so101_v2.stl"/>`` is named after its file (``base_so101_v2``) when
MuJoCo compiles it, and geoms refer to it by that name; so are unnamed textures and height fields.
The name exists only at compile time, so whatever changes or blanks the file before then (the file
check's stand-ins) or attaches the asset under a prefix (an assembly) would lose it: the rule is
applied once, on the parsed spec, and the asset keeps the name MuJoCo would have given it.
"""

from __future__ import annotations

from pathlib import PurePath

import mujoco


def file_stem(file: str) -> str:
    """The name MuJoCo gives an unnamed asset: its file name without folder and extension."""
    return PurePath(file.replace("\\", "/")).stem


def name_assets_after_files(spec: mujoco.MjSpec) -> None:
    """Give every unnamed mesh, texture and height field with a file the name MuJoCo would derive."""
    for asset in [*spec.meshes, *spec.textures, *spec.hfields]:
        if not asset.name and asset.file:
            asset.name = file_stem(asset.file)
