"""Spec robots in mjlab's own velocity task, as their specs' ``mjlab:`` blocks declare them.

Needs mjlab (``pip install -e ".[mjlab,urdf]" "torch==2.13.0+cpu"``; CI: .ci/mjlab); skipped, saying so,
where it is absent. Each run builds mjlab's rough terrain and steps on CPU: about 75 s.
"""

from __future__ import annotations

import re
import warnings
from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest

with warnings.catch_warnings():  # mjlab 1.6.0's own imports use torch.jit.script, deprecated in torch 2.13
    warnings.simplefilter("ignore", DeprecationWarning)
    pytest.importorskip("mjlab", reason='mjlab is not installed (pip install -e ".[mjlab]"; CI: .ci/mjlab)')
    torch = pytest.importorskip("torch")
    from mjlab.asset_zoo.robots.unitree_g1.g1_constants import get_g1_robot_cfg
    from mjlab.entity.entity import Entity
    from mjlab.envs import ManagerBasedRlEnv
    from mjlab.tasks.velocity.velocity_env_cfg import make_velocity_env_cfg

    from assembler.cli import main
    from assembler.errors import AssemblerError
    from assembler.mjlab import entity_cfg, for_mjlab
    from assembler.mjlab.task_parts import geom_lowest
    from assembler.mjlab.velocity import use_robot
    from assembler.registry.catalog import register_specs
    from assembler.registry.instances import assemble
    from assembler.urdf.packages import package_folders
    from tests.importers.test_limbs import QUADRUPED

DOCS = Path(__file__).parents[2] / "docs" / "gpu.md"


def _needs_urdf(name: str) -> None:
    if name == "G1" and not package_folders("example-robot-data"):
        pytest.skip('the G1 needs the urdf extra (pip install -e ".[urdf]")')


def test_the_docs_example_runs_mjlabs_velocity_task_with_the_shipped_biped_for_50_steps(
    capsys: pytest.CaptureFixture[str],
) -> None:
    (example,) = [
        block
        for block in re.findall(r"```python\n(.*?)```", DOCS.read_text(), flags=re.DOTALL)
        if "make_velocity_env_cfg" in block
    ]
    namespace: dict[str, object] = {}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(example, "docs/gpu.md", "exec"), namespace)
    env = namespace["env"]
    assert isinstance(env, ManagerBasedRlEnv)
    assert env.common_step_counter == 50 and "feet_ground_contact" in env.scene.sensors
    assert torch.isfinite(env.scene["robot"].data.joint_pos).all()
    printed = capsys.readouterr().out.splitlines()[-1]
    assert printed == "['robot/imu_ang_vel', 'robot/imu_lin_vel']"
    assert f"# {printed}" in example
    env.close()


def _fifty_steps(cfg: Any) -> tuple[ManagerBasedRlEnv, Any]:
    """mjlab's environment of ``cfg`` on CPU, reset and stepped 50 times with zero actions; the last reward."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # mjlab's and warp's notes about CPU-only runs
        env = ManagerBasedRlEnv(cfg, device="cpu")
        env.reset()
        actions = torch.zeros((env.num_envs, env.action_manager.total_action_dim))
        for _ in range(50):
            _, reward, _, _, _ = env.step(actions)
    return env, reward


def test_mjlabs_velocity_task_steps_50_times_with_the_shipped_g1_and_nothing_else_changed() -> None:
    _needs_urdf("G1")
    cfg = make_velocity_env_cfg()  # mjlab's task, for any robot: its per-robot slots are empty
    use_robot(cfg, "G1")
    env, reward = _fifty_steps(cfg)
    sensors = env.scene.sensors
    assert {"robot/imu_lin_vel", "robot/imu_ang_vel", "robot/root_angmom", "feet_ground_contact"} <= set(
        sensors
    )
    assert env.common_step_counter == 50
    assert torch.isfinite(reward).all() and torch.isfinite(env.scene["robot"].data.joint_pos).all()
    # mjlab's rule for its own G1: an action of 1 asks each servo for a quarter of its torque limit
    model, scale = env.sim.mj_model, cfg.actions["joint_pos"].scale
    assert isinstance(scale, dict) and len(scale) == model.nu == 29
    for actuator in range(model.nu):
        joint = model.joint(int(model.actuator_trnid[actuator, 0])).name.removeprefix("robot/")
        asked = model.actuator_gainprm[actuator, 0] * scale[re.escape(joint)]
        assert asked == pytest.approx(0.25 * model.actuator_forcerange[actuator, 1], rel=1e-12), joint
    env.close()


def test_a_quadruped_new_wrote_runs_mjlabs_velocity_task_as_written(tmp_path: Path) -> None:
    model = tmp_path / "dog.xml"
    model.write_text(QUADRUPED)
    spec = tmp_path / "dog.yaml"
    assert main(["new", str(model), "-o", str(spec)]) == 0  # its mjlab: block proposed, nothing added
    (robot,) = register_specs(spec)
    cfg = make_velocity_env_cfg()
    use_robot(cfg, robot.__name__)
    assert cfg.scene.entities["robot"].articulation.soft_joint_pos_limit_factor == 0.9
    named = cfg.scene.entities["robot"].spec_fn().compile()  # mjlab selects geoms by name: feet's get one
    assert named.geom("robot0_FL_foot_geom0").type == mujoco.mjtGeom.mjGEOM_SPHERE
    env, reward = _fifty_steps(cfg)
    assert {"robot/imu_lin_vel", "robot/imu_ang_vel", "feet_ground_contact"} <= set(env.scene.sensors)
    assert env.common_step_counter == 50 and torch.isfinite(reward).all()
    env.close()


@pytest.mark.parametrize(("name", "height"), [("BipedFree", 1.01433), ("G1", 0.7842)])
def test_a_floating_robot_spawns_with_its_lowest_collision_point_on_the_floor(
    name: str, height: float
) -> None:
    _needs_urdf(name)
    cfg = entity_cfg(name)
    # BipedFree: its MJCF's standing height (the soles on the floor); G1: mjlab's own G1 spawns at 0.7837
    assert cfg.init_state.pos[2] == pytest.approx(height, abs=1e-4)
    spec = cfg.spec_fn()  # our robot as mjlab gets it, put where mjlab puts it
    model = spec.compile()
    data = mujoco.MjData(model)
    free = model.jnt_qposadr[0]
    data.qpos[free : free + 3], data.qpos[free + 3 : free + 7] = cfg.init_state.pos, cfg.init_state.rot
    for joint, value in cfg.init_state.joint_pos.items():
        data.qpos[model.joint(joint.replace("\\", "")).qposadr[0]] = value
    mujoco.mj_kinematics(model, data)
    collision = [g for g in range(model.ngeom) if model.geom_contype[g] or model.geom_conaffinity[g]]
    assert min(geom_lowest(model, data, g) for g in collision) == pytest.approx(0.0, abs=1e-9)


def test_the_g1_floats_in_mjlab_with_its_motors_armature_and_mjlabs_joint_limit_factor() -> None:
    _needs_urdf("G1")
    model = for_mjlab("G1").get_model()  # the spec welds the pelvis; its mjlab block floats it
    assert model.jnt_type[0] == mujoco.mjtJoint.mjJNT_FREE
    # the 7520-22 knee motor's reflected inertia (specs/motors), not robosuite's 5/(i+1) rule
    assert model.joint("robot0_left_knee_joint").armature[0] == pytest.approx(0.0251019, rel=1e-5)
    assert entity_cfg("G1").articulation.soft_joint_pos_limit_factor == 0.9


def _contacts(model: mujoco.MjModel) -> dict[tuple[object, ...], int]:
    """How many geoms have each (contype, conaffinity, condim, priority, friction) setting."""
    found: dict[tuple[object, ...], int] = {}
    for g in range(model.ngeom):
        key = (
            *(int(getattr(model, f"geom_{f}")[g]) for f in ("contype", "conaffinity", "condim", "priority")),
            tuple(float(v) for v in model.geom_friction[g].round(6)),
        )
        found[key] = found.get(key, 0) + 1
    return found


def test_the_g1s_contacts_in_mjlab_are_mjlabs_own_g1s_full_collision() -> None:
    _needs_urdf("G1")
    ours = _contacts(Entity(entity_cfg("G1")).spec.compile())
    theirs = _contacts(Entity(get_g1_robot_cfg()).spec.compile())  # mjlab's G1, its FULL_COLLISION
    # the same settings, on as many geoms as each model has (its MJCF: 7 spheres a foot, ours 4)
    assert (
        set(ours)
        == set(theirs)
        == {
            (0, 0, 3, 0, (1.0, 0.005, 0.0001)),  # visual geoms
            (
                1,
                1,
                1,
                0,
                (1.0, 0.005, 0.0001),
            ),  # every other collision geom: frictionless, self-collisions on
            (1, 1, 3, 1, (0.6, 0.005, 0.0001)),  # the feet
        }
    )
    assert ours[(1, 1, 3, 1, (0.6, 0.005, 0.0001))] == 8


def test_robosuites_joint_rules_stay_out_of_an_mjlab_entity_unless_the_spec_asks() -> None:
    model = for_mjlab("BipedFree").get_model()
    # BipedFree's MJCF sets no armature, damping or friction loss; robosuite's rules would give the
    # first hip 5.0 kg m^2 (5/(i+1)) and every joint 0.1 damping and friction loss
    np.testing.assert_array_equal(model.dof_armature[6:], 0.0)
    np.testing.assert_array_equal(model.dof_damping[6:], 0.0)
    np.testing.assert_array_equal(model.dof_frictionloss[6:], 0.0)


def test_a_welded_robot_stays_where_its_home_pose_puts_it_unless_told() -> None:
    cfg = entity_cfg("Biped")  # the pelvis welded 1.01433 m above the floor, as the MJCF places it
    model = Entity(cfg).spec.compile()  # mjlab's entity: the robot under a mocap body at init_state.pos
    data = mujoco.MjData(model)
    mujoco.mj_forward(model, data)
    assert not any(t == mujoco.mjtJoint.mjJNT_FREE for t in model.jnt_type)
    assert cfg.init_state.pos == (0.0, 0.0, 0.0)
    np.testing.assert_allclose(data.body("robot0_pelvis").xpos, [0.0, 0.0, 1.01433])
    assert entity_cfg("Biped", pos=(0.0, 0.0, 0.2)).init_state.pos == (0.0, 0.0, 0.2)


def test_an_imu_body_the_robot_lacks_is_named_with_the_closest_body() -> None:
    robot = assemble("BipedFree", overrides=["mjlab.imu_body=pelviss"])
    with pytest.raises(
        AssemblerError, match=r"mjlab.imu_body: no body 'pelviss' in the robot. Did you mean 'pelvis'\?"
    ):
        entity_cfg(robot)
