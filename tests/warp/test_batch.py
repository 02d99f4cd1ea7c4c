"""A variant plan on MuJoCo Warp: each world is its variant's CPU model, in its fields and its motion."""

from __future__ import annotations

import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

import mujoco
import numpy as np
import pytest

pytest.importorskip("mujoco_warp", reason="MuJoCo Warp is not installed: pip install -e '.[warp]'")

import mujoco_warp  # noqa: E402

import assembler  # noqa: E402
from assembler.errors import AssemblerError  # noqa: E402
from assembler.warp import WarpBatch, put_variants  # noqa: E402
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan  # noqa: E402
from tests.conftest import TWO_LINK_MJCF  # noqa: E402

Write = Callable[[str, str], Path]

SITE = '<site name="right_center" pos="0.02 0 0.01" size="0.01"/>'
"""The two-link arm's base site, off the body's origin so that a size_scale moves it."""

PLAN = VariantPlan(
    "Sparrow7",
    fixed=(
        "bodies=[{match: link3, mass_scale: 1}, {match: 'link[45]', size_scale: 1}]",
        "geoms=[{match: 'link7_col*', friction: [1, 0.005, 0.0001]}]",
    ),
    grids=(Grid.parse("joint_defaults.damping=0.1,2.0"),),
    draws=(
        Draw.parse("bodies[0].mass_scale=0.7:1.3", "uniform"),
        Draw.parse("bodies[1].size_scale=0.85:1.15", "uniform"),
        Draw.parse("geoms[0].friction[0]=0.3:1.2", "uniform"),
    ),
    random=2,
    seed=7,
)
"""Four Sparrow7 worlds: two damping grid points, each with two draws of a link's mass, two links'
size and a geom's friction."""


@pytest.fixture(scope="module")
def batch() -> WarpBatch:
    return put_variants(PLAN)


def _cpu_model(overrides: list[str]) -> mujoco.MjModel:
    return assembler.assemble("Sparrow7", overrides=overrides).get_model(cache=False, store=False)


def test_every_world_holds_its_variants_values_in_every_varied_field(batch: WarpBatch) -> None:
    assert batch.nworld == 4
    assert {"dof_damping", "body_mass", "body_pos", "geom_size", "geom_friction", "body_subtreemass"} <= set(
        batch.varied
    )
    masses = set()
    for world, overrides in enumerate(batch.overrides):
        cpu = _cpu_model(overrides)
        masses.add(round(float(cpu.body_mass[cpu.body("robot0_link3").id]), 6))
        for name in batch.varied:
            ours = getattr(batch.model, name).numpy()[world]
            expected = getattr(cpu, name)
            np.testing.assert_allclose(
                ours.reshape(expected.shape), expected, rtol=2e-6, atol=2e-6, err_msg=name
            )
    assert len(masses) == 4  # the worlds differ


def test_every_world_moves_as_its_variant_does_on_cpu_for_20_steps(batch: WarpBatch) -> None:
    for _ in range(20):
        mujoco_warp.step(batch.model, batch.data)
    qpos = batch.data.qpos.numpy()
    for world, overrides in enumerate(batch.overrides):
        cpu = _cpu_model(overrides)
        data = mujoco.MjData(cpu)
        mujoco.mj_resetDataKeyframe(cpu, data, cpu.key("home").id)
        for _ in range(20):
            mujoco.mj_step(cpu, data)
        np.testing.assert_allclose(qpos[world], data.qpos, atol=1e-4)


SITED_PLAN = VariantPlan(
    "Sited",
    fixed=("bodies=[{match: base, size_scale: 1}]",),
    grids=(Grid.parse("bodies[0].size_scale=1,1.2"),),
)
"""The two-link arm's base (which holds the site 'right_center') at its size and 1.2 times it."""


def test_a_site_moves_with_a_size_scale_and_keeps_its_size_on_cpu_and_warp(write: Write) -> None:
    write("r/twolink.xml", TWO_LINK_MJCF.replace('<site name="right_center" size="0.01"/>', SITE))
    assembler.register_specs(write("r/robot.yaml", "name: Sited\nmjcf: twolink.xml\n"))
    batch = put_variants(SITED_PLAN)
    plain, scaled = (assembler.assemble("Sited", overrides=o).get_model(cache=False) for o in batch.overrides)
    site = plain.site("robot0_right_center").id
    np.testing.assert_allclose(scaled.site_pos[site], 1.2 * plain.site_pos[site])
    np.testing.assert_array_equal(scaled.site_size[site], plain.site_size[site])
    assert "site_size" not in batch.varied
    np.testing.assert_allclose(batch.model.site_pos.numpy()[1][site], scaled.site_pos[site], rtol=1e-6)


def test_a_touch_sensors_zone_scales_on_cpu_and_is_refused_on_warp_saying_why(write: Write) -> None:
    touch = '  <sensor><touch name="pad" site="right_center"/></sensor>\n  <keyframe>'
    write(
        "r/twolink.xml",
        TWO_LINK_MJCF.replace('<site name="right_center" size="0.01"/>', SITE).replace("  <keyframe>", touch),
    )
    assembler.register_specs(write("r/robot.yaml", "name: Sited\nmjcf: twolink.xml\n"))
    plain, scaled = (
        assembler.assemble("Sited", overrides=[*SITED_PLAN.fixed, *more]).get_model(cache=False)
        for more in ([], ["bodies[0].size_scale=1.2"])
    )
    site = plain.site("robot0_right_center").id
    assert scaled.site_size[site][0] == pytest.approx(1.2 * plain.site_size[site][0])  # a sphere: its radius
    with pytest.raises(AssemblerError) as caught:
        put_variants(SITED_PLAN)
    assert str(caught.value) == (
        "world 1 (bodies[0].size_scale=1.2): varies site_size (a touch or contact sensor's zone, whose size "
        "follows its body's size_scale), which MuJoCo Warp cannot vary per world "
        "(fields it can vary start with '*' in mujoco_warp's types.Model); build such variants as separate models"
    )


def test_a_plan_changing_a_count_is_refused_naming_the_field() -> None:
    plan = VariantPlan("Sparrow7", grids=(Grid.parse("remove_free_joint=false,true"),))
    with pytest.raises(
        AssemblerError, match=r"^world 1 \(remove_free_joint=true\): remove_free_joint: not a patchable field"
    ):
        put_variants(plan)


def test_without_mujoco_warp_the_import_error_gives_the_install_line() -> None:
    code = "import sys; sys.modules['mujoco_warp'] = None; import assembler.warp"
    result = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=False)
    assert result.returncode == 1
    assert result.stderr.strip().splitlines()[-1] == (
        "ImportError: assembler.warp needs MuJoCo Warp (Python >= 3.11): pip install -e '.[warp]' "
        "(or pip install 'robot-assembler[warp]')"
    )
