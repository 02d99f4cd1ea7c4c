"""The MJCF files robosuite reads for our parts, kept in the cache across processes.

Each case makes a robosuite environment in new Python processes sharing one private cache folder,
and watches (``sys.setprofile``) which of the bridge's builders ran: the part's spec
(``part_mjspec``), the assembly (``build_mjspec``) and the lossless emission (``lossless_xml``). What
a process wrote is read off the cache folder's files (inode and modification time), never off a clock.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from assembler.cache.content import CONVERTED, PARTS  # noqa: E402
from assembler.cache.file_state import file_digest  # noqa: E402
from assembler.urdf.packages import package_folders  # noqa: E402
from tests.robosuite.processes import result, user_folder  # noqa: E402

BUILDERS = ("part_mjspec", "build_mjspec", "lossless_xml")

MAKE = """
import json, sys
ran = set()
def watch(frame, event, arg):
    code = frame.f_code
    if event == "call" and code.co_name in {builders!r} and "assembler" in code.co_filename:
        ran.add(code.co_name)
import warnings
import assembler.robosuite, robosuite
sys.setprofile(watch)
with warnings.catch_warnings(record=True) as caught:
    warnings.simplefilter("always")
    env = robosuite.make(
        "Lift", robots={robot!r}, has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False
    )
    env.reset()
sys.setprofile(None)
said = sorted({{str(w.message) for w in caught if w.category.__name__ == "AssemblerWarning"}})
m = env.sim.model
robot = [i for i in range(m.nbody) if "cube" not in m.body(i).name]  # the cube is drawn at random
model = [m.nbody, float(m.body_mass[robot].sum()), float(m.dof_damping.sum()),
         float(m.dof_armature.sum()), float(abs(m.jnt_range).sum())]
print("RESULT " + json.dumps({{"ran": sorted(ran), "model": model, "said": said}}))
"""


def make(robot: str, cache: Path, cwd: Path, **variables: str) -> Any:
    """Make Lift with ``robot`` (and reset it once) in a new process sharing ``cache``."""
    code = MAKE.format(builders=BUILDERS, robot=robot)
    return result(code, cwd, ASSEMBLER_CACHE_DIR=str(cache), **variables)


def kept(cache: Path) -> dict[str, tuple[int, int]]:
    """Every file of the part-file folder, by name: (inode, modification time)."""
    return {path.name: (path.stat().st_ino, path.stat().st_mtime_ns) for path in (cache / PARTS).iterdir()}


def texts(cache: Path) -> list[Path]:
    """The part files (the records beside them excluded)."""
    return sorted((cache / PARTS).glob("text-*.xml"))


def test_a_second_process_makes_the_environment_from_the_kept_files_and_writes_none(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    first = make("Sparrow7", cache, tmp_path)
    assert set(first["ran"]) == set(BUILDERS)
    assert len(texts(cache)) == 4  # the robot, its gripper and base alone, and their assembly
    before = kept(cache)
    second = make("Sparrow7", cache, tmp_path)
    assert second["ran"] == []  # no part spec built, no assembly, no emission
    assert kept(cache) == before  # no file written, replaced or touched
    assert second["model"] == first["model"]


def test_a_part_file_edited_in_the_cache_is_made_again_never_simulated(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    first = make("Sparrow7", cache, tmp_path)
    edited = 0
    for path in texts(cache):  # every joint's armature, in every file with joints, 9 plus what it was
        text = path.read_text()
        path.write_text(text.replace(' armature="', ' armature="9'))
        edited += ' armature="' in text
    assert edited >= 3  # the robot, its gripper, the assembly
    second = make("Sparrow7", cache, tmp_path)
    assert "lossless_xml" in second["ran"]
    assert second["model"] == first["model"]  # robosuite read the files made again, not the edited
    for path in texts(cache):
        assert path.name == f"text-{file_digest(path)}.xml"  # each file whole: what its name says


def test_a_changed_mjcf_or_spec_makes_a_new_file(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    folder = user_folder(tmp_path, "Wren")
    variables = {"ASSEMBLER_ROBOSUITE_SPECS": str(folder)}
    first = make("Wren", cache, tmp_path, **variables)
    before = set(kept(cache))
    model_file = folder / "assets" / "sparrow7.xml"
    stat = model_file.stat()  # the MJCF edited, its size and modification time kept (touch -r)
    model_file.write_text(
        model_file.read_text().replace('range="-2.8973 2.8973"', 'range="-2.5973 2.5973"', 1)
    )
    os.utime(model_file, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    assert (model_file.stat().st_size, model_file.stat().st_mtime_ns) == (stat.st_size, stat.st_mtime_ns)
    edited = make("Wren", cache, tmp_path, **variables)
    assert "lossless_xml" in edited["ran"]
    assert edited["model"][4] == pytest.approx(first["model"][4] - 0.6)  # the narrower range simulated
    assert len(new_texts(cache, before)) == 2  # the robot alone and the assembly; gripper and base kept
    before = set(kept(cache))
    spec_file = folder / "wren.yaml"
    spec_file.write_text(spec_file.read_text().replace("  damping: 0.1\n", "  damping: 0.3\n"))
    respecified = make("Wren", cache, tmp_path, **variables)
    assert "lossless_xml" in respecified["ran"]
    assert respecified["model"][2] > edited["model"][2] + 0.5  # the joints' default damping raised by 0.2
    assert len(new_texts(cache, before)) == 2


def new_texts(cache: Path, before: set[str]) -> list[str]:
    """The part files in the cache whose names are not in ``before``."""
    return [path.name for path in texts(cache) if path.name not in before]


@pytest.mark.skipif(
    not package_folders("example-robot-data"), reason='needs the urdf extra: pip install ".[urdf]"'
)
def test_what_the_emission_said_a_warm_make_says_again(tmp_path: Path) -> None:
    cache = tmp_path / "cache"
    first = make("UR5", cache, tmp_path)  # its URDF has no right_center site: added for robosuite, said
    assert any("right_center" in message for message in first["said"])
    for mesh in (cache / CONVERTED).iterdir():  # made just now: too new to be recorded (racy)
        os.utime(mesh, ns=(mesh.stat().st_atime_ns, mesh.stat().st_mtime_ns - 10**10))
    make("UR5", cache, tmp_path)  # the part files recorded with the converted meshes they name
    warm = make("UR5", cache, tmp_path)
    assert warm["ran"] == []
    assert warm["said"] == first["said"]
