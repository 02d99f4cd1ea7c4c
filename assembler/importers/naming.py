"""The registry name ``assembler new`` gives a robot: from the file's own model name, else from its
file name, as a Python class name, and never one a registered spec already has."""

from __future__ import annotations

import re
from collections.abc import Collection
from pathlib import Path

GENERIC_STEMS = frozenset({"robot", "model", "main", "scene", "index", "urdf", "mjcf"})
"""File names that say nothing about the robot (robosuite's ``robot.xml``): the folder is used instead."""

GENERIC_FOLDERS = frozenset({"assets", "xml", "mjcf", "urdf", "models", "model", "robots", "robot", "scenes"})
"""Folder names that say nothing about the robot in them."""

MUJOCO_UNNAMED = "MuJoCo Model"
"""The model name MuJoCo gives a file whose ``<mujoco>`` has no ``model`` attribute."""

GENERIC_NAMES = frozenset(
    {MUJOCO_UNNAMED.lower(), "physics", "robot", "model", "default", "main", "scene", "urdf", "plane"}
)
"""Model names that say nothing about the robot (pybullet's ``pr2_gripper.urdf`` is
``<robot name="physics">``): the file name is used instead."""


def camel_case(text: str) -> str:
    """``so101_new_calib`` -> ``So101NewCalib``: words joined, each capitalized, digits kept."""
    words = [word for word in re.split(r"[^A-Za-z0-9]+", text) if word]
    name = "".join(word[:1].upper() + word[1:] for word in words)
    if not name or not name[0].isalpha():
        name = "Robot" + name
    return name[:64]


def name_source(model_name: str, path: Path, scene: bool = False) -> str:
    """What the name is made from: the file's model name unless it is a generic word, else its stem, else
    its folder's name (a
    task scene's stem names the task: gymnasium-robotics' ``fetch/reach.xml`` is the Fetch)."""
    if model_name and model_name.strip().lower() not in GENERIC_NAMES:
        return model_name
    if not scene and path.stem.lower() not in GENERIC_STEMS:
        return path.stem
    if path.parent.name.lower() in GENERIC_FOLDERS:  # gym-aloha's assets/bimanual_viperx_transfer_cube.xml
        return path.stem
    return path.parent.name or path.stem


def free_name(wanted: str, taken: Collection[str], suffix: str) -> str:
    """``wanted``, else ``wanted`` + ``suffix`` (``Z1Arm``), else with a number (``Z1Arm2``), whichever
    no registered spec and no robosuite class has (case ignored, as on case-blind file systems)."""
    lowered = {item.lower() for item in taken}
    candidates = [wanted, wanted + suffix] if not wanted.endswith(suffix) else [wanted]
    number = 2
    while all(name.lower() in lowered for name in candidates):
        candidates.append(f"{wanted}{suffix if not wanted.endswith(suffix) else ''}{number}")
        number += 1
    return next(name for name in candidates if name.lower() not in lowered)
