"""What the benchmarks compare: the robots (ours and robosuite's), robosuite's own assembly of a
robot (as ``robosuite.robots.Robot.load_model`` does it), and the scale test's scene."""

from __future__ import annotations

from pathlib import Path

import assembler
from assembler.files.paths import package_root, shipped_specs_dir
from assembler.spec.schema import SceneSpec
from assembler.worlds.scene import Scene, build_scene

SCALE_ROBOT = "Sparrow7"


def robosuite_installed() -> bool:
    """True when robosuite can be imported."""
    return package_root("robosuite") is not None


def _spec_folder(cls: type) -> Path | None:
    loaded = getattr(cls, "loaded", None)
    return Path(loaded.document.file).resolve().parent if loaded is not None else None


def robosuite_robots() -> list[str]:
    """Robots registered from ``specs/robosuite/robots`` (whatever is there today), by name."""
    folder = (shipped_specs_dir() / "robosuite" / "robots").resolve()
    return [name for name, cls in assembler.REGISTERED_ROBOTS.items() if _spec_folder(cls) == folder]


def own_robots() -> list[str]:
    """The robots this project ships with its own MJCF (the top of ``specs/``)."""
    folder = shipped_specs_dir().resolve()
    return [name for name, cls in assembler.REGISTERED_ROBOTS.items() if _spec_folder(cls) == folder]


def scale_scene(count: int) -> Scene:
    """``count`` Sparrow7 robots, each with its default base and gripper, one metre apart."""
    robots = [{"robot": SCALE_ROBOT, "pos": (float(i % 8), float(i // 8), 0.0)} for i in range(count)]
    spec = SceneSpec.model_validate({"kind": "scene", "name": f"scale{count}", "robots": robots})
    return build_scene(spec)
