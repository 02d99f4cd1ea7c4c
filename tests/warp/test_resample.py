"""Worlds by the plan's laws (validated once, values in arrays) and re-randomized in place: each world
is still its variant's CPU model."""

from __future__ import annotations

import dataclasses
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

pytest.importorskip("mujoco_warp", reason="MuJoCo Warp is not installed: pip install -e '.[warp]'")

import assembler  # noqa: E402
from assembler.errors import SpecError  # noqa: E402
from assembler.warp import WarpBatch, put_variants  # noqa: E402
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan  # noqa: E402
from tests.patch.test_patchable import DECLARED, DECLARED_MJCF  # noqa: E402

Write = Callable[[str, str], Path]

PLAN = VariantPlan(
    "Sparrow7",
    fixed=(
        "bodies=[{match: link3, mass_scale: 1}, {match: 'link[45]', size_scale: 1}]",
        "joints=[{match: joint2, armature: 0.1}]",
    ),
    grids=(Grid.parse("joint_defaults.damping=0.05,0.1,0.2,0.4"),),
    draws=(
        Draw.parse("bodies[0].mass_scale=0.8:1.2", "uniform"),
        Draw.parse("bodies[1].size_scale=0.85:1.15", "uniform"),
        Draw.parse("joints[0].armature=0.05:0.5", "uniform"),
    ),
    random=1024,
    seed=3,
)
"""4,096 Sparrow7 worlds: four dampings, each with 1,024 draws of a link's mass, two links' size and
a joint's armature."""


def _cpu_model(overrides: list[str]) -> mujoco.MjModel:
    return assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)


def _assert_world_is_its_cpu_model(batch: WarpBatch, world: int) -> None:
    cpu = _cpu_model(batch.world_overrides(world))
    for name in batch.varied:
        expected = getattr(cpu, name)
        ours = getattr(batch.model, name).numpy()[world].reshape(expected.shape)
        np.testing.assert_allclose(ours, expected, rtol=2e-6, atol=2e-6, err_msg=f"world {world}: {name}")


@pytest.fixture(scope="module")
def batch() -> WarpBatch:
    return put_variants(PLAN)


def test_4096_worlds_come_from_the_plans_laws_and_sampled_ones_equal_their_cpu_models(
    batch: WarpBatch,
) -> None:
    assert batch.nworld == 4096
    assert batch.effects is not None  # not patched world by world
    assert {"body_mass", "body_pos", "geom_size", "dof_armature", "dof_damping", "actuator_biasprm"} <= set(
        batch.varied
    )
    for world in (0, 1, 1500, 4095):
        _assert_world_is_its_cpu_model(batch, world)


def test_dof_length_under_a_size_scale_is_listed_with_why_each_world_keeps_the_robots(
    batch: WarpBatch,
) -> None:
    assert set(batch.nominal) == {"dof_length"}
    assert "sleeping only" in batch.nominal["dof_length"]
    assert not np.array_equal(_cpu_model(batch.world_overrides(5)).dof_length, batch.cpu_model.dof_length)


def test_resample_writes_new_draws_into_the_same_model_and_leaves_other_worlds(batch: WarpBatch) -> None:
    pointers = {name: getattr(batch.model, name).ptr for name in batch.varied}
    before = batch.model.body_mass.numpy().copy()
    old = [batch.variant(w) for w in (7, 8)]
    batch.resample([7, 2049], seed=11)
    assert {name: getattr(batch.model, name).ptr for name in batch.varied} == pointers  # in place
    after = batch.model.body_mass.numpy()
    assert np.array_equal(np.flatnonzero((after != before).any(axis=1)), [7, 2049])
    assert batch.variant(7) == dataclasses.replace(PLAN, seed=11).variant(7) != old[0]
    assert batch.variant(8) == old[1]
    for world in (7, 2049, 8):
        _assert_world_is_its_cpu_model(batch, world)


def test_a_plan_outside_the_laws_is_patched_world_by_world_and_still_exact() -> None:
    plan = VariantPlan(
        "Sparrow7",
        fixed=("bodies=[{match: link3, mass_scale: 1}]",),
        grids=(Grid.parse("bodies[0].size_scale=0.9,1.1"),),  # a grid and a draw on one body's mass
        draws=(Draw.parse("bodies[0].mass_scale=0.8:1.2", "uniform"),),
        random=2,
        seed=5,
    )
    batch = put_variants(plan)
    assert batch.effects is None
    batch.resample([3], seed=8)
    for world in (0, 3):
        _assert_world_is_its_cpu_model(batch, world)


def test_plan_columns_are_the_values_of_each_variant() -> None:
    positions, drawn = PLAN.columns([0, 5, 4095])
    for column, index in enumerate([0, 5, 4095]):
        variant = PLAN.variant(index)
        assert (
            PLAN.grids[0].values[positions["joint_defaults.damping"][column]]
            == variant["joint_defaults.damping"]
        )
        assert {key: drawn[key][column] for key in drawn} == {d.key: variant[d.key] for d in PLAN.draws}


def test_a_uniform_range_is_validated_once_at_its_bounds() -> None:
    plan = VariantPlan(
        "Sparrow7",
        fixed=("bodies=[{match: link3, mass_scale: 1}]",),
        draws=(Draw.parse("bodies[0].mass_scale=0:1", "uniform"),),  # 0 is no mass factor
        random=4,
    )
    with pytest.raises(
        SpecError, match=r"^--uniform bodies\[0\].mass_scale: Input should be greater than 0$"
    ):
        put_variants(plan)


def test_a_normal_draw_beyond_the_values_validated_is_validated_when_resampled() -> None:
    plan = VariantPlan(
        "Sparrow7",
        fixed=("bodies=[{match: link3, mass_scale: 1}]",),
        draws=(Draw.parse("bodies[0].mass_scale=1:0.05", "normal"),),
        random=4,
    )
    batch = put_variants(plan)
    assert batch.effects is not None
    low, high = batch.effects.validated["bodies[0].mass_scale"]
    batch.effects.validate({"bodies[0].mass_scale": np.array([high + 0.5])})  # valid: the range widens
    assert batch.effects.validated["bodies[0].mass_scale"] == (low, high + 0.5)
    with pytest.raises(SpecError, match=r"^--normal bodies\[0\].mass_scale: Input should be greater than 0$"):
        batch.effects.validate({"bodies[0].mass_scale": np.array([0.5, -0.2])})


def test_actuator_gains_and_gears_drawn_per_world_equal_their_cpu_models_dampratio_included(
    write: Write,
) -> None:
    write("d/twolink.xml", DECLARED_MJCF)
    assembler.register_specs(write("d/declared.yaml", DECLARED))
    plan = VariantPlan(
        "Declared",
        draws=(
            Draw.parse("actuators[0].kp=150:300", "uniform"),  # a position servo with a dampratio
            Draw.parse("actuators[1].gear=1:3", "uniform"),
        ),
        random=16,
        seed=4,
    )
    batch = put_variants(plan)
    assert batch.effects is not None and batch.effects.dampratio
    assert {"actuator_gainprm", "actuator_biasprm", "actuator_gear", "actuator_acc0"} <= set(batch.varied)
    batch.resample([2, 9], seed=21)
    for world in (0, 2, 9, 15):
        cpu = assembler.assemble("Declared", overrides=batch.world_overrides(world)).get_model(cache=False)
        for name in batch.varied:
            expected = getattr(cpu, name)
            ours = getattr(batch.model, name).numpy()[world].reshape(expected.shape)
            np.testing.assert_allclose(ours, expected, rtol=2e-6, atol=2e-6, err_msg=f"world {world}: {name}")
