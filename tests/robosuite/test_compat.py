"""robosuite's statements that newer MuJoCo breaks are patched inside robosuite, by what this MuJoCo
does, and nothing of the ``mujoco`` module that other libraries see changes.

Each case runs in its own interpreter (the patches change robosuite's classes for the process). The
expected state of every patch is asked of this MuJoCo by the patch's own probe, so the same tests
hold on 3.9 (nothing needed) and on 4.0 (all three applied).
"""

from __future__ import annotations

import importlib.util
import os
from pathlib import Path

import mujoco
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from assembler.robosuite.compat import PATCHES  # noqa: E402
from tests.robosuite.processes import ROOT, result, run  # noqa: E402

NEEDED = {patch.name: patch.needed() for patch in PATCHES}

SEEN_BY_OTHERS = """
import types, mujoco, numpy as np
def seen():
    model = mujoco.MjModel.from_xml_string('<mujoco><worldbody><body><joint/><geom size=".1"/></body></worldbody></mujoco>')
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    try:  # the call of this MuJoCo's signature, then the old one: result or the error's type
        dense = np.zeros((1, 1)); mujoco.mj_fullM(model, data, dense); full_m = dense.tolist()
    except TypeError as error:
        full_m = type(error).__name__
    try:
        dense = np.zeros((1, 1)); mujoco.mj_fullM(model, dense, data.qM); old_full_m = dense.tolist()
    except (AttributeError, TypeError) as error:
        old_full_m = type(error).__name__
    hinge, slide = mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE
    return {
        "hinge == np.int32(3)": bool(hinge == np.int32(3)),
        "np.int32(3) in (hinge, slide)": np.int32(3) in (hinge, slide),
        "mj_fullM": full_m,
        "old mj_fullM": old_full_m,
        "mj_fullM object": id(mujoco.mj_fullM),
        # submodules robosuite imports (mujoco.viewer, mujoco.egl) appear as attributes: not ours
        "mujoco names": sorted(n for n in dir(mujoco) if not isinstance(getattr(mujoco, n), types.ModuleType)),
        "MjData names": sorted(dir(mujoco.MjData)),
        "mjtJoint names": sorted(dir(mujoco.mjtJoint)),
    }
before = seen()
import assembler.robosuite, robosuite
from assembler.robosuite import compat
import json
print("RESULT " + json.dumps({"before": before, "after": seen(), "states": {p.name: compat.state(p) for p in compat.PATCHES}}))
"""


def _expected_state(name: str) -> str:
    return "applied" if NEEDED[name] else "not needed"


def test_importing_the_bridge_patches_what_this_mujoco_needs_and_leaves_mujoco_as_others_see_it(
    tmp_path: Path,
) -> None:
    seen = result(SEEN_BY_OTHERS, tmp_path)
    assert seen["after"] == seen["before"]
    assert {name: state.split(":")[0] for name, state in seen["states"].items()} == {
        name: _expected_state(name) for name in NEEDED
    }


def test_check_prints_one_line_per_patch_with_its_state(tmp_path: Path) -> None:
    done = run(["-m", "assembler.robosuite", "--check"], tmp_path)
    assert done.returncode == 0, done.stderr[-3000:]
    lines = done.stdout.splitlines()
    assert lines[0].startswith("MuJoCo ") and ", robosuite 1.5.2" in lines[0]
    assert [line.split(" (")[0] for line in lines[1:]] == list(NEEDED)
    for line, name in zip(lines[1:], NEEDED, strict=True):
        assert line.split("): ")[1].startswith(_expected_state(name)), line


def _robosuite_with_one_statement_changed(root: Path) -> Path:
    """A copy of the installed robosuite (files linked) whose ``binding_utils.py`` no longer holds the
    joint-type assert the patches replace: the robosuite release that changed it, as far as we can tell."""
    spec = importlib.util.find_spec("robosuite")
    assert spec is not None and spec.origin is not None
    installed = Path(spec.origin).parent
    copy = root / "changed" / "robosuite"
    copy.mkdir(parents=True)
    for entry in installed.iterdir():
        if entry.name != "utils":
            os.symlink(entry, copy / entry.name)
    (copy / "utils").mkdir()
    for entry in (installed / "utils").iterdir():
        if entry.name != "binding_utils.py":
            os.symlink(entry, copy / "utils" / entry.name)
    text = (installed / "utils" / "binding_utils.py").read_text()
    old = "assert joint_type in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)"
    assert text.count(old) == 2
    changed = text.replace(old, "assert int(joint_type) in (2, 3)  # robosuite's own fix")
    (copy / "utils" / "binding_utils.py").write_text(changed)
    return copy.parent


def test_a_patch_whose_statement_robosuite_no_longer_holds_is_skipped_and_said_in_one_line(
    tmp_path: Path,
) -> None:
    changed = _robosuite_with_one_statement_changed(tmp_path)
    done = run(["-m", "assembler.robosuite", "--check"], tmp_path, PYTHONPATH=f"{ROOT}{os.pathsep}{changed}")
    assert done.returncode == 0, done.stderr[-3000:]
    assert "robosuite 1.5.2" in done.stdout
    states = dict(line.split("): ", 1) for line in done.stdout.splitlines()[1:])
    for kind in ("qpos", "qvel"):
        where = f"joint-{kind}-address (robosuite.utils.binding_utils.MjModel.get_joint_{kind}_addr"
        expected = (
            f"skipped: robosuite.utils.binding_utils.MjModel.get_joint_{kind}_addr no longer holds "
            "`assert joint_type in (mujoco.mjtJoint.mjJNT_HINGE, mujoco.mjtJoint.mjJNT_SLIDE)` once"
        )
        assert states[where] == expected
        said = [line for line in done.stderr.splitlines() if f"patch joint-{kind}-address" in line]
        line = f"assembler.robosuite: patch joint-{kind}-address {expected}; robosuite may fail on MuJoCo {mujoco.__version__}"
        assert said == ([line] if NEEDED[f"joint-{kind}-address"] else [])  # said where it matters
    assert states["mass-matrix (robosuite.controllers.parts.controller.Controller.update"].startswith(
        _expected_state("mass-matrix")
    )
