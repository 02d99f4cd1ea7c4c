"""MuJoCo's own load of a vendor's file, the reference the corpus compares our build with: an MJCF
as ``MjModel.from_xml_path`` reads it; a URDF through MuJoCo's URDF import with bodies unfused (so
that they correspond one to one), visual geoms kept, mesh paths as written (``package://NAME/``
resolved through ROS_PACKAGE_PATH, as a user sets it) and MuJoCo's ``balanceinertia`` where the
spec balances inertias."""

from __future__ import annotations

import os
import re
from pathlib import Path
from typing import Any

import mujoco


def _packages(text: str) -> str:
    for folder in filter(None, os.environ.get("ROS_PACKAGE_PATH", "").split(os.pathsep)):
        for package in set(re.findall(r"package://([^/]+)/", text)):
            if (Path(folder) / package).is_dir():
                text = text.replace(f"package://{package}/", f"{Path(folder) / package}/")
    return text


def direct_load(path: Path, urdf: bool, spec: Any) -> mujoco.MjModel:
    """The vendor's file as MuJoCo alone loads it."""
    if not urdf:
        return mujoco.MjModel.from_xml_path(str(path))
    balance = str(bool(spec.balance_inertia)).lower()
    compiler = (
        f'<mujoco><compiler fusestatic="false" discardvisual="false" strippath="false" '
        f'meshdir="{path.parent}" balanceinertia="{balance}"/></mujoco>'
    )
    text = re.sub(r"(<robot[^>]*>)", lambda match: match.group(1) + compiler, path.read_text(), count=1)
    return mujoco.MjSpec.from_string(_packages(text)).compile()
