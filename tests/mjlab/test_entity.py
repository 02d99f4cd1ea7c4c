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

    from assembler.cli import main
    from assembler.errors import AssemblerError
    from assembler.files.paths import display_path
    from assembler.mjlab import entity_cfg, home_joint_positions, mapped_actuators
    from assembler.registry.catalog import register_specs
    from assembler.registry.instances import assemble
    from assembler.urdf.packages import package_folders
    from tests.importers.test_limbs import QUADRUPED

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


def _docs_feet_only_spec() -> str:
    """docs/gpu.md's example of ``mjlab.collisions``: mjlab's feet-only setting for the shipped biped."""
    docs = (Path(__file__).parents[2] / "docs" / "gpu.md").read_text()
    (example,) = [b for b in re.findall(r"```yaml\n(.*?)```", docs, flags=re.DOTALL) if "collisions:" in b]
    return example


def test_the_docs_feet_only_collisions_leave_only_the_feet_touching_the_terrain(tmp_path: Path) -> None:
    spec = tmp_path / "feet_only.yaml"
    spec.write_text(_docs_feet_only_spec())
    register_specs(spec)
    model = Entity(entity_cfg("BipedFeetOnly")).spec.compile()  # the robot as mjlab builds it
    feet = {"robot0_l_foot_col", "robot0_r_foot_col"}
    for geom in range(model.ngeom):
        name = model.geom(geom).name
        if name in feet:  # the terrain's contype 1 meets their conaffinity 1; their contype 0 meets no foot
            assert (model.geom_contype[geom], model.geom_conaffinity[geom]) == (0, 1), name
            assert (model.geom_condim[geom], model.geom_priority[geom]) == (3, 1), name
            # foot_friction, applied after the list, sets the sliding friction; the MJCF's other two stay
            np.testing.assert_allclose(model.geom_friction[geom], [0.6, 0.005, 0.0001])
        else:
            assert (model.geom_contype[geom], model.geom_conaffinity[geom]) == (0, 0), name
    assert len(feet & {model.geom(g).name for g in range(model.ngeom)}) == 2


NO_MATCH_SPEC = """\
name: BipedTypo
extends: BipedFree
mjlab:
  collisions:
    - geoms: ["[lr]_foot_col", "l_fot_col"]
      condim: 3
"""


def test_a_collision_pattern_that_matches_no_geom_is_one_line_at_its_spec_line(tmp_path: Path) -> None:
    spec = tmp_path / "typo.yaml"
    spec.write_text(NO_MATCH_SPEC)
    register_specs(spec)
    with pytest.raises(AssemblerError) as caught:
        entity_cfg("BipedTypo")
    assert str(caught.value) == (
        f"{display_path(spec)}:5:32: mjlab.collisions[0].geoms[1]: 'l_fot_col' matches no geom of the robot "
        "(whole names, as the MJCF writes them without the prefix 'robot0_'). Did you mean 'l_foot_col'?"
    )


def test_unnamed_geoms_are_matched_and_named_as_body_geom_i(tmp_path: Path) -> None:
    model = tmp_path / "dog.xml"
    model.write_text(QUADRUPED)  # no geom has a name
    assert main(["new", str(model), "-o", str(tmp_path / "dog.yaml")]) == 0
    (dog,) = register_specs(tmp_path / "dog.yaml")
    (tmp_path / "quiet.yaml").write_text(
        f"name: QuietDog\nextends: {dog.__name__}\nmjlab:\n  collisions:\n"
        "    - {geoms: ['.*_(hip|thigh)_geom0'], contype: 0, conaffinity: 0}\n"
    )
    register_specs(tmp_path / "quiet.yaml")
    compiled = Entity(entity_cfg("QuietDog")).spec.compile()
    for leg in ("FL", "FR", "RL", "RR"):
        for part in ("hip", "thigh"):
            geom = compiled.geom(f"robot0_{leg}_{part}_geom0")
            assert (geom.contype[0], geom.conaffinity[0]) == (0, 0)
        foot = compiled.geom(f"robot0_{leg}_foot_geom0")  # no entry names the feet: the MJCF's 1 and 1
        assert (foot.contype[0], foot.conaffinity[0]) == (1, 1)
