"""A plan's uniform draws over arrays are the numbers each world's own generator draws."""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("mujoco_warp", reason="MuJoCo Warp is not installed: pip install -e '.[warp]'")

from assembler.warp.seeded_draws import plan_columns, uniform_columns  # noqa: E402
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan  # noqa: E402

DRAWS = (
    Draw.parse("bodies[0].mass_scale=0.8:1.2", "uniform"),
    Draw.parse("joints[0].armature=-3:5.5", "uniform"),
    Draw.parse("geoms[0].friction[0]=0.3:0.3", "uniform"),
)


@pytest.mark.parametrize("seed", [0, 1, 7, 12345, 2**32 - 1])
def test_uniform_draws_over_arrays_equal_default_rng_of_seed_and_index_exactly(seed: int) -> None:
    indices = [*range(3000), 2**31, 2**32 - 1]
    ours = uniform_columns(seed, indices, DRAWS)
    generators = (np.random.default_rng([seed, index]) for index in indices)
    expected = np.array([[draw.sample(rng) for draw in DRAWS] for rng in generators]).T
    assert ours is not None
    assert np.array_equal(ours, expected)


def test_a_normal_draw_or_a_seed_of_2_to_the_32_is_left_to_the_generators() -> None:
    assert uniform_columns(0, [1, 2], (Draw.parse("a=1:0.1", "normal"),)) is None
    assert uniform_columns(2**32, [1, 2], DRAWS) is None
    assert uniform_columns(0, [2**32], DRAWS) is None


@pytest.mark.parametrize(("law", "mass"), [("uniform", "0.9:1.1"), ("normal", "1:0.1")])
def test_plan_columns_are_the_plans_own_variants(law: str, mass: str) -> None:
    plan = VariantPlan(
        "Sparrow7",
        grids=(Grid.parse("joint_defaults.damping=0.1,0.2,0.4"), Grid.parse("joint_defaults.armature=0,1")),
        draws=(
            Draw.parse(f"bodies[0].mass_scale={mass}", law),
            Draw.parse("joints[0].armature=0.1:0.5", "uniform"),
        ),  # type: ignore[arg-type]
        random=5,
        seed=3,
    )
    indices = [0, 4, 5, 17, 29]
    positions, drawn = plan_columns(plan, indices)
    for column, index in enumerate(indices):
        variant = plan.variant(index)
        assert {grid.key: grid.values[positions[grid.key][column]] for grid in plan.grids} | {
            key: drawn[key][column] for key in drawn
        } == variant
