"""The assembly of a robot means what its file means: with the joint rules switched off and no base
or grippers, the assembled model equals MuJoCo's own compile of the file in every field.

Every field of ``MjModel`` is compared generically (each array, each size, each field of ``opt``,
``vis`` and ``stat``), so none can be forgotten; a field of a kind the comparison does not know
fails the test. The only fields left out of the generic comparison are listed in :data:`EXCLUDED`
with the reason, and each is compared in its own way below.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

import assembler
from assembler.mjcf import COLLISION_GROUP
from assembler.mjcf.installed_mujoco import mujoco_at_least
from assembler.models.part import PartModel
from tests.models.semantics_robots import CASES, CUBE_OBJ, SLEEVE_SKN, robot_mjcf

PREFIX = "robot0_"

EXCLUDED: dict[str, str] = {
    r"names|names_map|nnames|nnames_map|name_\w+adr": "names gain the robot prefix; compared one by one",
    r"paths|npaths|\w+_pathadr": "asset paths are made absolute; compared as the files they name",
    r"nbuffer": "the size of the buffer holding the (longer) names and paths",
    r"nkey|key_\w+": "the file's keyframes give way to the assembly's one 'home' keyframe (issue #2102)",
    r"signature": "MuJoCo's checksum of the whole model, which covers the names and keyframes above",
}
"""Fields outside the generic comparison (a regular expression of names) and why."""

STRUCTS = ("opt", "vis", "stat")
"""Fields that hold structures; each of their fields is compared."""

OBJECTS: dict[mujoco.mjtObj, str] = {
    mujoco.mjtObj.mjOBJ_BODY: "nbody",
    mujoco.mjtObj.mjOBJ_JOINT: "njnt",
    mujoco.mjtObj.mjOBJ_GEOM: "ngeom",
    mujoco.mjtObj.mjOBJ_SITE: "nsite",
    mujoco.mjtObj.mjOBJ_CAMERA: "ncam",
    mujoco.mjtObj.mjOBJ_LIGHT: "nlight",
    mujoco.mjtObj.mjOBJ_MESH: "nmesh",
    mujoco.mjtObj.mjOBJ_SKIN: "nskin",
    mujoco.mjtObj.mjOBJ_HFIELD: "nhfield",
    mujoco.mjtObj.mjOBJ_TEXTURE: "ntex",
    mujoco.mjtObj.mjOBJ_MATERIAL: "nmat",
    mujoco.mjtObj.mjOBJ_PAIR: "npair",
    mujoco.mjtObj.mjOBJ_EXCLUDE: "nexclude",
    mujoco.mjtObj.mjOBJ_EQUALITY: "neq",
    mujoco.mjtObj.mjOBJ_TENDON: "ntendon",
    mujoco.mjtObj.mjOBJ_ACTUATOR: "nu",
    mujoco.mjtObj.mjOBJ_SENSOR: "nsensor",
    mujoco.mjtObj.mjOBJ_NUMERIC: "nnumeric",
    mujoco.mjtObj.mjOBJ_TEXT: "ntext",
    mujoco.mjtObj.mjOBJ_TUPLE: "ntuple",
    mujoco.mjtObj.mjOBJ_FLEX: "nflex",
}
"""Every kind of named object a robot file can hold, with its count."""

PATHS = {"mesh_pathadr": "nmesh", "skin_pathadr": "nskin", "hfield_pathadr": "nhfield", "tex_pathadr": "ntex"}


def _struct_fields(prefix: str, value: Any) -> dict[str, Any]:
    fields: dict[str, Any] = {}
    for name in dir(value):
        item = getattr(value, name)
        if name.startswith("_") or callable(item) or name[0].isupper():
            continue
        if isinstance(item, (np.ndarray, int, float)):
            fields[f"{prefix}.{name}"] = item
        else:
            fields.update(_struct_fields(f"{prefix}.{name}", item))
    return fields


def model_fields(model: mujoco.MjModel) -> dict[str, Any]:
    """Every field of ``model``: arrays, sizes, text and the fields of its structures."""
    fields: dict[str, Any] = {}
    for name in dir(model):
        value = getattr(model, name)
        if name.startswith("_") or callable(value):
            continue
        if name in STRUCTS:
            fields.update(_struct_fields(name, value))
        elif isinstance(value, (np.ndarray, int, float, bytes)):
            fields[name] = value
        else:
            raise AssertionError(f"MjModel.{name} is a {type(value).__name__}; teach this test to compare it")
    return fields


def _excluded(field: str) -> bool:
    return any(re.fullmatch(pattern, field) for pattern in EXCLUDED)


def _same(ours: Any, theirs: Any) -> bool:
    if isinstance(theirs, np.ndarray):
        return bool(ours.shape == theirs.shape and np.array_equal(ours, theirs, equal_nan=True))
    return bool(ours == theirs)


SKIN_FILE_CASES = {"skin-from-a-file"}
"""Cases MuJoCo before 3.17 cannot attach (the bones a skin file names keep no prefix): refused."""

CASE_NAMES = [
    pytest.param(
        name,
        marks=pytest.mark.skipif(
            name in SKIN_FILE_CASES and not mujoco_at_least(3, 17),
            reason=f"MuJoCo {mujoco.__version__} cannot attach a skin file's bones; the refusal is tested",
        ),
    )
    for name in CASES
]


def _compile_both(
    folder: Path, name: str, more_spec: str = ""
) -> tuple[mujoco.MjModel, mujoco.MjModel, PartModel]:
    (folder / "cube.obj").write_text(CUBE_OBJ)
    (folder / "sleeve.skn").write_bytes(SLEEVE_SKN)
    (folder / "robot.xml").write_text(robot_mjcf(name))
    (folder / "robot.yaml").write_text(
        "name: Case\nmjcf: robot.xml\njoint_defaults: {frictionloss: null, damping: null, armature: null}\n"
        + more_spec
    )
    (cls,) = assembler.register_specs(folder / "robot.yaml")
    robot = cls(idn=0)
    return robot.get_model(), mujoco.MjModel.from_xml_path(str(folder / "robot.xml")), robot


def test_there_are_at_least_thirty_robot_files() -> None:
    assert len(CASES) >= 30


@pytest.mark.parametrize("name", CASE_NAMES)
def test_the_assembled_robot_equals_mujocos_compile_of_its_file(tmp_path: Path, name: str) -> None:
    ours, theirs, _ = _compile_both(tmp_path, name)
    mine, reference = model_fields(ours), model_fields(theirs)
    assert mine.keys() == reference.keys()
    compared = [field for field in reference if not _excluded(field)]
    assert [field for field in compared if not _same(mine[field], reference[field])] == []
    assert len(compared) > 300  # the generic comparison sees the whole model, not a handful of fields


@pytest.mark.parametrize("name", CASE_NAMES)
def test_every_name_is_the_files_name_with_the_robot_prefix(tmp_path: Path, name: str) -> None:
    ours, theirs, _ = _compile_both(tmp_path, name)
    for kind, count in OBJECTS.items():
        assert getattr(ours, count) == getattr(theirs, count), count
        for index in range(getattr(theirs, count)):
            own = mujoco.mj_id2name(theirs, kind, index)
            expected = own if own in (None, "world") else PREFIX + own
            assert mujoco.mj_id2name(ours, kind, index) == expected, (kind, index)


@pytest.mark.parametrize(
    "name", [case for case in CASE_NAMES if case.values[0] in ("meshes", "skin-from-a-file")]
)
def test_every_asset_path_names_the_same_file(tmp_path: Path, name: str) -> None:
    ours, theirs, _ = _compile_both(tmp_path, name)
    for field, count in PATHS.items():
        for index in range(getattr(theirs, count)):
            mine, reference = (_path(model, field, index) for model in (ours, theirs))
            assert mine == (str(tmp_path / reference) if reference else ""), (field, index)


def _path(model: mujoco.MjModel, field: str, index: int) -> str:
    start = getattr(model, field)[index]
    return "" if start < 0 else model.paths[start:].split(b"\0", 1)[0].decode()


@pytest.mark.parametrize("name", ["materials-and-textures", "meshes", "default-classes", "frames"])
def test_robosuites_collision_colour_recolours_only_collision_geoms(tmp_path: Path, name: str) -> None:
    ours, theirs, robot = _compile_both(tmp_path, name, "collision_colour: robosuite\n")
    collision = theirs.geom_group == COLLISION_GROUP
    assert collision.any() and (~collision).any()
    assert np.array_equal(ours.geom_rgba[~collision], theirs.geom_rgba[~collision])
    assert np.array_equal(ours.geom_matid[~collision], theirs.geom_matid[~collision])
    assert np.array_equal(
        ours.geom_rgba[collision], np.tile(np.float32(robot.collision_rgba), (collision.sum(), 1))
    )
    assert set(ours.geom_matid[collision]) == {-1}
    assert robot.conventions_applied() == [
        "collision geoms (group 0) lose their materials and are coloured 0 0.5 0 1 (collision_colour: robosuite)"
    ]


def test_without_robosuites_collision_colour_every_geom_keeps_its_files_look(tmp_path: Path) -> None:
    ours, theirs, robot = _compile_both(tmp_path, "materials-and-textures")
    assert (theirs.geom_group == COLLISION_GROUP).any() and (theirs.geom_matid >= 0).any()
    assert np.array_equal(ours.geom_rgba, theirs.geom_rgba)
    assert np.array_equal(ours.geom_matid, theirs.geom_matid)
    assert robot.conventions_applied() == []


@pytest.mark.skipif(mujoco_at_least(3, 17), reason="MuJoCo 3.17 and later attach a skin file's bones")
def test_a_skin_file_is_refused_where_mujoco_cannot_attach_its_bones(tmp_path: Path) -> None:
    with pytest.raises(
        assembler.MjcfError, match=r"skin 'sleeve_file' reads its bones from .*sleeve.skn, which MuJoCo 3"
    ):
        _compile_both(tmp_path, "skin-from-a-file")


def test_the_files_keyframes_give_way_to_one_home_keyframe_at_qpos0(tmp_path: Path) -> None:
    ours, theirs, _ = _compile_both(tmp_path, "keyframes-in-the-file")
    assert (theirs.nkey, ours.nkey, ours.key(0).name) == (2, 1, "home")
    assert np.array_equal(ours.key_qpos[0], ours.qpos0)
