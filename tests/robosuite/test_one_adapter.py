"""The bridge as one adapter: robosuite gets one class per robot, gripper and base, and each model
file is read once per process however many environments are made and reset.

Each case runs in its own Python process (robosuite's registries are module globals) and reads the
classes alive in it (``type.__subclasses__``, recursively), and which model files the assembler
parsed (``sys.setprofile`` on the MJCF reader).
"""

from __future__ import annotations

from pathlib import Path

import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.processes import result  # noqa: E402

MADE_AND_RESET = """
import collections, json, sys
parsed = collections.Counter()
def watch(frame, event, arg):
    code = frame.f_code
    if event == "call" and code.co_name == "_load" and code.co_filename.endswith("mjcf/source.py"):
        parsed[str(frame.f_locals["path"])] += 1
import assembler.robosuite, robosuite
from assembler.models import REGISTERED_ROBOTS
sys.setprofile(watch)
kwargs = dict(has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
envs = [robosuite.make("Lift", robots="Sparrow7", **kwargs) for _ in range(2)]
for env in envs:
    env.reset()
    env.reset()
sys.setprofile(None)
def classes(root):
    for sub in type.__subclasses__(root):
        yield sub
        yield from classes(sub)
names = collections.defaultdict(list)
for cls in set(classes(object)):
    if cls.__name__ in ("Sparrow7", "PincerGripper", "Pedestal"):
        names[cls.__name__].append(cls.__module__)
model = envs[0].robots[0].robot_model
print("RESULT " + json.dumps({
    "classes": {name: sorted(modules) for name, modules in names.items()},
    "assembly_class_is_the_spec_class": type(model.assembly) is REGISTERED_ROBOTS["Sparrow7"],
    "parsed": sorted(parsed.values()),
}))
"""


def test_robosuite_gets_one_class_per_part_and_each_model_file_is_read_once(tmp_path: Path) -> None:
    seen = result(MADE_AND_RESET, tmp_path)
    robosuites = {"Sparrow7": "robot_class", "PincerGripper": "part_classes", "Pedestal": "part_classes"}
    for name, module in robosuites.items():  # ours (the catalog's), and robosuite's one class of it
        assert seen["classes"][name] == ["assembler.registry.catalog", f"assembler.robosuite.{module}"]
    assert seen["assembly_class_is_the_spec_class"]
    assert seen["parsed"] == [1, 1, 1]  # the robot's, gripper's and base's model files, once each
