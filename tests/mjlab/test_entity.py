"""Our robots as mjlab entities, stepped in 8 environments by mjlab itself on CPU.

Needs mjlab (``pip install -e ".[mjlab,urdf]" "torch==2.13.0+cpu"``; CI: .ci/mjlab), which pins
MuJoCo ~=3.11; skipped, saying so, where it is absent.
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
    from mjlab.actuator import (
        BuiltinDcMotorActuatorCfg,
        BuiltinPositionActuatorCfg,
        DcMotorInputMode,
        XmlActuatorCfg,
    )
    from mjlab.entity.entity import Entity
    from mjlab.envs import ManagerBasedRlEnv, ManagerBasedRlEnvCfg
    from mjlab.envs.mdp.actions import JointPositionActionCfg
    from mjlab.scene import SceneCfg

    from assembler.errors import AssemblerError
    from assembler.mjlab import entity_cfg, home_joint_positions, mapped_actuators
    from assembler.registry.catalog import register_specs
    from assembler.registry.instances import assemble
    from assembler.urdf.packages import package_folders

ENVS = 8


def run_envs(cfg: Any, steps: int = 25) -> tuple[ManagerBasedRlEnv, np.ndarray]:
    """mjlab's RL environment with ``ENVS`` copies of the entity, stepped with zero actions (each
    servo targets its default, the home pose); the joint positions after ``steps`` steps."""
    env_cfg = ManagerBasedRlEnvCfg(
        decimation=2,
        scene=SceneCfg(num_envs=ENVS, entities={"robot": cfg}),
        actions={"joints": JointPositionActionCfg(entity_name="robot", actuator_names=(".*",), scale=0.5)},
        episode_length_s=10.0,
    )
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # mjlab's and warp's notes about CPU-only runs
        env = ManagerBasedRlEnv(env_cfg, device="cpu")
        env.reset()
        actions = torch.zeros((ENVS, env.action_manager.total_action_dim))
        for _ in range(steps):
            env.step(actions)
    return env, env.scene["robot"].data.joint_pos.cpu().numpy()


def test_a_yaml_robot_with_its_own_actuators_holds_its_home_pose_in_8_mjlab_environments() -> None:
    robot = assemble("Sparrow7")
    _, home = home_joint_positions(robot.get_model())
    cfg = entity_cfg(robot)
    (actuators,) = cfg.articulation.actuators
    assert isinstance(actuators, XmlActuatorCfg)
    env, joint_pos = run_envs(cfg)
    entity = env.scene["robot"]
    assert list(entity.joint_names) == list(home)
    assert joint_pos.shape == (ENVS, len(home))
    # every world started at the home pose and its servos hold it (gravity pulls, within 0.05 rad)
    np.testing.assert_allclose(joint_pos, np.tile(list(home.values()), (ENVS, 1)), atol=0.05)
    env.close()


def test_a_urdf_robot_with_its_yaml_servos_mapped_to_mjlabs_builtin_actuators_steps_8_environments() -> None:
    if not package_folders("example-robot-data"):
        pytest.skip('the URDF robots need the urdf extra (pip install -e ".[urdf]")')
    robot = assemble("UR5")
    model = robot.get_model()
    cfg = entity_cfg(robot, actuators="builtin")
    configs = cfg.articulation.actuators
    assert all(isinstance(c, BuiltinPositionActuatorCfg) for c in configs)
    # the spec's servos (kp 2000/kv 400 on the large joints, 500/100 on the wrists), and the URDF's efforts
    gains = {c.target_names_expr[0]: (c.stiffness, c.damping, c.effort_limit) for c in configs}
    assert gains["robot0_shoulder_pan_joint"] == (2000.0, 400.0, 150.0)
    assert gains["robot0_wrist_3_joint"] == (500.0, 100.0, 28.0)
    assert len(configs) == model.nu == 6
    env, joint_pos = run_envs(cfg)
    # mjlab built its own actuators from ours: same count, the assembly's were left out of the spec
    assert env.sim.mj_model.nu == 6
    _, home = home_joint_positions(model)
    np.testing.assert_allclose(joint_pos, np.tile(list(home.values()), (ENVS, 1)), atol=0.05)
    env.close()


def test_an_actuator_mjlab_has_no_builtin_for_is_named_with_what_to_do() -> None:
    model = mujoco.MjModel.from_xml_string(
        '<mujoco><worldbody><body><joint name="j"/><geom size="0.1"/></body></worldbody>'
        '<actuator><velocity name="spin" joint="j" kv="3"/></actuator></mujoco>'
    )
    with pytest.raises(
        AssemblerError, match=r"spin: neither a position servo, a motor nor a DC motor .*use actuators='xml'"
    ):
        mapped_actuators(model)


VOLTAGE_SPEC = """\
name: VoltageSparrow
extends: Sparrow7
motors:
  - {match: joint7, motor: MaxonECmax22, gear_ratio: 20, efficiency: 0.8, control: voltage}
"""
"""Sparrow7 with a maxon motor taking volts on joint 7 (a 20:1 gearbox, 80% efficient)."""


def test_a_dc_motor_taking_volts_is_mjlabs_own_dcmotor_with_our_actuators_fields(tmp_path: Path) -> None:
    spec = tmp_path / "voltage_sparrow.yaml"
    spec.write_text(VOLTAGE_SPEC)
    register_specs(spec)
    robot = assemble("VoltageSparrow")
    ours = robot.get_model()
    cfg = entity_cfg(robot, actuators="builtin")
    (motor,) = [c for c in cfg.articulation.actuators if isinstance(c, BuiltinDcMotorActuatorCfg)]
    assert motor.target_names_expr == ("robot0_joint7",) and motor.mode == DcMotorInputMode.VOLTAGE
    theirs = Entity(cfg).spec.compile()  # mjlab's entity, its actuators made by mjlab
    mine, its = ours.actuator("robot0_joint7").id, theirs.actuator("robot0_joint7").id
    for field in ("gaintype", "biastype", "dyntype", "gainprm", "biasprm", "dynprm", "gear"):
        np.testing.assert_array_equal(
            getattr(theirs, f"actuator_{field}")[its], getattr(ours, f"actuator_{field}")[mine], err_msg=field
        )


def test_the_spec_mjlab_gets_is_a_fresh_copy_without_our_keyframe() -> None:
    cfg = entity_cfg("Sparrow7")
    first, second = cfg.spec_fn(), cfg.spec_fn()
    assert first is not second
    assert len(first.keys) == 0 and len(first.actuators) == len(second.actuators) > 0


def test_the_docs_mjlab_example_runs_and_prints_what_it_says(capsys: pytest.CaptureFixture[str]) -> None:
    docs = (Path(__file__).parents[2] / "docs" / "gpu.md").read_text()
    (example,) = [
        block
        for block in re.findall(r"```python\n(.*?)```", docs, flags=re.DOTALL)
        if "mjlab" in block and "ResampleAtReset" in block
    ]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        exec(compile(example, "docs/gpu.md", "exec"), {})
    printed = capsys.readouterr().out.splitlines()[-1]
    assert printed == "torch.Size([8, 9])"
    assert f'print(env.scene["robot"].data.joint_pos.shape)  # {printed}' in example
