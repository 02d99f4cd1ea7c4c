"""What the benchmarks compare: the robots (ours and robosuite's), robosuite's own assembly of a
robot (as ``robosuite.robots.Robot.load_model`` does it), and the scale test's scene."""

from __future__ import annotations

from pathlib import Path

import assembler
from assembler.paths import package_root, shipped_specs_dir
from assembler.scene import Scene, build_scene
from assembler.schema import SceneSpec

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


def robosuite_xml(name: str, idn: int = 0) -> str:
    """robosuite's MJCF of a robot with its default base and grippers (robots/robot.py:161-223)."""
    from robosuite.models.bases import robot_base_factory
    from robosuite.models.grippers import gripper_factory
    from robosuite.models.robots import create_robot
    from robosuite.utils.mjcf_utils import array_to_string

    model = create_robot(name, idn=idn)
    if model.default_base is not None:
        model.add_base(robot_base_factory(model.default_base, idn=idn))
    for arm in model.arms:
        gripper = gripper_factory(model.default_gripper[arm], idn=f"{idn}_{arm}")
        root = gripper.worldbody.find("body")
        if arm in model.gripper_mount_pos_offset:
            root.set("pos", array_to_string(model.gripper_mount_pos_offset[arm]))
        if arm in model.gripper_mount_quat_offset:
            root.set("quat", array_to_string(model.gripper_mount_quat_offset[arm]))
        model.add_gripper(gripper, model.eef_name[arm])
    return str(model.get_xml())


def scale_scene(count: int) -> Scene:
    """``count`` Sparrow7 robots, each with its default base and gripper, one metre apart."""
    robots = [{"robot": SCALE_ROBOT, "pos": (float(i % 8), float(i // 8), 0.0)} for i in range(count)]
    spec = SceneSpec.model_validate({"kind": "scene", "name": f"scale{count}", "robots": robots})
    return build_scene(spec)
