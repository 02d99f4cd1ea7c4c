"""A variant patched onto the compiled robot equals the variant compiled from scratch, field by field."""

from __future__ import annotations

import copy
from collections.abc import Callable
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

import assembler
from assembler.errors import SpecError
from assembler.patch.derived import apply_patch
from assembler.patch.patchable import PATCHABLE, NotPatchable, model_patch, patched_model
from assembler.patch.resolved import Resolved, resolve_variant
from assembler.spec.documents import parse_overrides
from tests.conftest import TWO_LINK_MJCF
from tests.models.test_physical import CUBE_OBJ, MESH_MJCF

Write = Callable[[str, str], Path]

DECLARED = """\
name: Declared
mjcf: twolink.xml
init_qpos: [0.5, -0.5]
actuators:
  - {match: shoulder, kp: 200, dampratio: 1, ctrlrange: [-3, 3], forcerange: [-50, 50]}
  - {match: elbow, type: general, gainprm: [80], biasprm: [0, -80, -4], gear: 2, ctrlrange: [-2, 2]}
"""
"""Two actuators the spec declares (so an override can reach their gains), on the two-link arm."""

DECLARED_MJCF = TWO_LINK_MJCF.replace(
    '<site name="right_center"', '<light name="lamp" pos="0.1 0 0.6"/>\n      <site name="right_center"'
).replace("  <keyframe>", '  <sensor><touch name="base_touch" site="right_center"/></sensor>\n  <keyframe>')
"""The two-link arm with a light in its base body, so that scaling the base moves a light too, and a
touch sensor whose zone is the base's site, so that the site's size is scaled too."""

CASES: list[tuple[str, dict[str, Any]]] = [
    ("Sparrow7", {"joint_defaults.damping": 0.35}),
    ("Sparrow7", {"joint_defaults.frictionloss": 0.02}),
    ("Sparrow7", {"joint_defaults.armature": {"inverse_index": 2.0}}),
    ("Sparrow7", {"joints": [{"match": "joint[24]", "stiffness": 3.0, "armature": 0.4}]}),
    ("Sparrow7", {"bodies": [{"match": "link3", "mass_scale": 1.4}]}),
    ("Sparrow7", {"bodies": [{"match": "link[2-5]", "size_scale": 1.2}]}),
    ("Sparrow7", {"bodies": [{"match": "link4", "size_scale": 0.8, "mass_scale": 1.1}]}),
    ("Sparrow7", {"geoms": [{"match": "*_col*", "friction": [0.6, 0.01, 0.001]}]}),
    ("Sparrow7", {"init_qpos": [0.1, -0.5, 0.0, -2.0, 0.0, 1.4, 0.6]}),
    ("Declared", {"actuators[0].kp": 350}),
    ("Declared", {"actuators[0].dampratio": 0.4}),
    ("Declared", {"actuators[1].gainprm": [60], "actuators[1].biasprm": [0, -60, -2]}),
    ("Declared", {"actuators[1].gear": 3}),
    ("Declared", {"actuators[0].ctrlrange": [-2, 2.5], "actuators[0].forcerange": [-20, 30]}),
    ("Declared", {"bodies": [{"match": "link1", "size_scale": 1.3}]}),
    ("Declared", {"bodies": [{"match": "base", "size_scale": 0.9}]}),
]


DRAWING_STATISTICS = ("stat.extent", "stat.center", "stat.meansize")
"""What a patch leaves at the compiled robot's values (patchable.DERIVED says why): only drawing reads them."""


def _model_arrays(model: mujoco.MjModel) -> dict[str, np.ndarray]:
    """Every array field of a compiled model, read generically, with opt's and stat's numbers."""
    arrays = {
        name: value for name in dir(model) if isinstance(value := getattr(model, name, None), np.ndarray)
    }
    for struct in ("opt", "stat"):
        for name in dir(getattr(model, struct)):
            value = getattr(getattr(model, struct), name)
            key = f"{struct}.{name}"
            if (
                isinstance(value, (float, int, np.ndarray))
                and not name.startswith("_")
                and key not in DRAWING_STATISTICS
            ):
                arrays[key] = np.asarray(value)
    return arrays


def _register_declared(write: Write) -> None:
    write("d/twolink.xml", DECLARED_MJCF)
    assembler.register_specs(write("d/declared.yaml", DECLARED))


def _both_ways(
    robot: str, overrides: dict[str, Any]
) -> tuple[list[mujoco.MjModel], mujoco.MjModel, list[str]]:
    """The variant patched (its tables resolved in full, and against the robot's MJCF), and compiled."""
    base = assembler.assemble(robot)
    model = base.get_model(cache=False, store=False)
    variant = assembler.assemble(robot, overrides=overrides)
    compiled = variant.get_model(cache=False, store=False)
    light = resolve_variant(base, Resolved.of(base), parse_overrides(overrides))
    patch = model_patch(model, Resolved.of(base), light)
    lightly = copy.copy(model)
    apply_patch(lightly, patch)
    return [patched_model(model, base, variant), lightly], compiled, patch.fields


@pytest.mark.parametrize(
    ("robot", "overrides"), CASES, ids=[next(iter(o)) + f"-{i}" for i, (_, o) in enumerate(CASES)]
)
def test_a_patched_variant_equals_its_full_compile_in_every_model_field(
    write: Write, robot: str, overrides: dict[str, Any]
) -> None:
    _register_declared(write)
    both, compiled, fields = _both_ways(robot, overrides)
    assert fields, "the variant changed nothing"
    theirs = _model_arrays(compiled)
    for patched in both:
        ours = _model_arrays(patched)
        assert ours.keys() == theirs.keys()
        different = [
            name
            for name in theirs
            if ours[name].shape != theirs[name].shape
            or not np.allclose(ours[name], theirs[name], rtol=1e-10, atol=1e-10, equal_nan=True)
        ]
        assert different == [], {name: (ours[name], theirs[name]) for name in different[:3]}


def test_the_cases_write_every_model_field_the_table_names(write: Write) -> None:
    _register_declared(write)
    written = {name for robot, overrides in CASES for name in _both_ways(robot, overrides)[2]}
    named = {name for fields in PATCHABLE.values() for name in fields}
    assert named - written == set()


@pytest.mark.parametrize(
    ("overrides", "message"),
    [
        ({"remove_free_joint": True}, "remove_free_joint: not a patchable field"),
        ({"bodies": [{"match": "*", "size_scale": 1.1}]}, "size_scale of '(base|link1)' scales its meshes"),
        ({"actuators": [{"match": "j1", "kp": 10}]}, "actuators: the variant has other actuators"),
    ],
)
def test_a_structural_change_is_refused_with_the_field_it_changes(
    write: Write, overrides: dict[str, Any], message: str
) -> None:
    write("m/block.obj", CUBE_OBJ)
    write("m/meshy.xml", MESH_MJCF)
    assembler.register_specs(write("m/meshy.yaml", "name: Meshy\nmjcf: meshy.xml\n"))
    base = assembler.assemble("Meshy")
    model = base.get_model(cache=False, store=False)
    with pytest.raises(NotPatchable, match=message):
        model_patch(model, Resolved.of(base), Resolved.of(assembler.assemble("Meshy", overrides=overrides)))


def test_a_variant_value_the_schema_refuses_is_named_by_its_flag() -> None:
    base = assembler.assemble("Sparrow7")
    items = parse_overrides({"joint_defaults.damping": -0.2}, "--normal ")
    with pytest.raises(SpecError, match=r"^--normal joint_defaults.damping: "):
        resolve_variant(base, Resolved.of(base), items)


def test_a_variant_list_of_the_wrong_length_is_named_by_its_flag() -> None:
    base = assembler.assemble("Sparrow7")
    items = parse_overrides({"joint_defaults.damping": [0.1, 0.2]}, "--grid ")
    with pytest.raises(
        SpecError, match=r"--grid joint_defaults.damping: expected 7 values \(one per joint\), got 2"
    ):
        resolve_variant(base, Resolved.of(base), items)
