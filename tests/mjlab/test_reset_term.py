"""A plan re-drawn at mjlab's resets (``assembler.warp.reset_term``; here, where CI's mjlab stage runs
it): the term writes each reset environment's new values into mjlab's MuJoCo Warp model in place,
equal to the CPU model of the drawn overrides."""

from __future__ import annotations

import warnings

import numpy as np
import pytest

pytest.importorskip("mujoco_warp", reason="MuJoCo Warp is not installed: pip install -e '.[warp]'")
with warnings.catch_warnings():  # mjlab 1.6.0's own imports use torch.jit.script, deprecated in torch 2.13
    warnings.simplefilter("ignore")
    pytest.importorskip("mjlab", reason='mjlab is not installed (pip install -e ".[mjlab]"; CI: .ci/mjlab)')
    torch = pytest.importorskip("torch")
    from mjlab.envs import ManagerBasedRlEnv, ManagerBasedRlEnvCfg
    from mjlab.envs.mdp.actions import JointPositionActionCfg
    from mjlab.managers.event_manager import EventTermCfg
    from mjlab.scene import SceneCfg

import assembler  # noqa: E402
from assembler.mjlab import entity_cfg  # noqa: E402
from assembler.warp.plan_effects import compiler_dampratio_rule  # noqa: E402
from assembler.warp.reset_term import ResampleAtReset  # noqa: E402
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan  # noqa: E402

PLAN = VariantPlan(
    "Sparrow7",
    fixed=(
        "bodies=[{match: link3, mass_scale: 1}, {match: 'link[45]', size_scale: 1}]",
        "joints=[{match: joint2, armature: 0.1}]",
        "geoms=[{match: 'link7_col*', friction: [1, 0.005, 0.0001]}]",
    ),
    grids=(Grid.parse("joint_defaults.damping=0.1,0.4"),),
    draws=(
        Draw.parse("bodies[0].mass_scale=0.7:1.3", "uniform"),
        Draw.parse("bodies[1].size_scale=0.85:1.15", "uniform"),
        Draw.parse("joints[0].armature=0.05:0.5", "uniform"),
        Draw.parse("geoms[0].friction[0]=0.3:1.2", "uniform"),
    ),
    random=2,
    seed=1,
)
"""Four Sparrow7 worlds: two dampings, each with draws of a link's mass, two links' size, a joint's
armature and a geom's friction."""

FIELDS = (
    "body_mass",
    "body_inertia",
    "body_pos",
    "dof_damping",
    "dof_armature",
    "geom_size",
    "geom_friction",
)
KINDS = ("body", "body", "body", "jnt", "jnt", "geom", "geom")


def test_the_reset_term_writes_each_reset_worlds_draws_into_mjlabs_model_as_the_cpu_model_has_them() -> None:
    term = ResampleAtReset(PLAN)
    robot = assembler.assemble(PLAN.robot, overrides=list(PLAN.fixed))
    cfg = ManagerBasedRlEnvCfg(
        decimation=2,
        scene=SceneCfg(num_envs=4, entities={"robot": entity_cfg(robot)}),
        actions={"joints": JointPositionActionCfg(entity_name="robot", actuator_names=(".*",), scale=0.5)},
        events={"plan": EventTermCfg(func=term, mode="reset")},
        episode_length_s=10.0,
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # mjlab's and warp's notes about CPU-only runs
        env = ManagerBasedRlEnv(cfg, device="cpu")
        env.reset()  # every environment: the term's first call (seed 2)
        model = env.sim.wp_model
        pointers = {name: getattr(model, name).ptr for name in term.model_fields}
        before = model.body_mass.numpy().copy()
        env.reset(env_ids=torch.tensor([1, 3]))  # two environments: the second call (seed 3)
        for _ in range(5):
            env.step(torch.zeros((4, env.action_manager.total_action_dim)))
    assert {name: getattr(model, name).ptr for name in term.model_fields} == pointers  # in place
    theirs = env.sim.mj_model
    after = model.body_mass.numpy()
    assert np.array_equal(np.flatnonzero((after != before).any(axis=1)), [1, 3])
    for world, seed in ((0, 2), (1, 3), (3, 3)):
        variant = PLAN.variant(world) | {
            d.key: v for d, v in zip(PLAN.draws, _draws(seed, world), strict=True)
        }
        overrides = [*PLAN.fixed, *(f"{key}={value}" for key, value in variant.items())]
        cpu = assembler.assemble(PLAN.robot, overrides=overrides).get_model(cache=False, store=False)
        for name, kind in zip(FIELDS, KINDS, strict=True):
            for element in range({"body": cpu.nbody, "jnt": cpu.njnt, "geom": cpu.ngeom}[kind]):
                label = {"body": cpu.body, "jnt": cpu.joint, "geom": cpu.geom}[kind](element).name
                if element == 0 and kind == "body":
                    continue
                assert getattr(model, name).shape[0] == 4, f"{name}: not expanded per world"
                ours = getattr(model, name).numpy()[world]
                if kind != "jnt":
                    row = (theirs.body if kind == "body" else theirs.geom)("robot/" + label).id
                    expected = getattr(cpu, name)[element]
                else:
                    row = theirs.jnt_dofadr[theirs.joint("robot/" + label).id]
                    expected = getattr(cpu, name)[cpu.jnt_dofadr[element]]
                np.testing.assert_allclose(
                    ours[row], expected, rtol=2e-6, err_msg=f"world {world} {name} {label}"
                )
    env.close()


def _draws(seed: int, world: int) -> list[float]:
    rng = np.random.default_rng([seed, world])
    return [draw.sample(rng) for draw in PLAN.draws]


def test_a_plan_varying_nothing_a_dampratio_reads_keeps_its_laws_on_any_mujoco() -> None:
    plan = VariantPlan(
        "Sparrow7",
        fixed=("geoms=[{match: 'link7_col*', friction: [1, 0.005, 0.0001]}]",),
        grids=(Grid.parse("joint_defaults.damping=0.1,2.0"),),
        draws=(Draw.parse("geoms[0].friction[0]=0.3:1.2", "uniform"),),
        random=2,
    )
    term = ResampleAtReset(plan)  # MuJoCo 3.11 (mjlab's) resolves dampratios by another rule than 4
    assert term.effects is not None
    if compiler_dampratio_rule() == "diagonal":  # left at their compiled values: nothing they read varies
        assert term.effects.dampratio == {}
    assert {"dof_damping", "geom_friction"} <= set(term.model_fields)
