"""Every shipped spec validates and builds; every sensible robot x base x gripper combination
compiles, holds its home pose under its own actuators and simulates one second without NaN.

New specs are tested by being added to ``specs/``: nobody has to write a test for them.
"""

from __future__ import annotations

import itertools

import mujoco
import numpy as np
import pytest

import assembler
from assembler.files.paths import PACKAGE_SCHEME, shipped_specs_dir
from assembler.spec.spec_files import load_paths

# robosuite's parts (specs/robosuite, read from the installed package) are covered by test_parity.py.
LOADED = [s for s in load_paths([shipped_specs_dir()]) if not s.spec.source_file.startswith(PACKAGE_SCHEME)]
ROBOTS = [s.spec.name for s in LOADED if s.spec.kind == "robot"]  # type: ignore[attr-defined]
BASES = [s.spec.name for s in LOADED if s.spec.kind == "base"]  # type: ignore[attr-defined]
GRIPPERS = [s.spec.name for s in LOADED if s.spec.kind == "gripper"]  # type: ignore[attr-defined]


def _sensible_bases(robot: str) -> list[str | None]:
    """Single arms go on every base; bimanual torsos and humanoids stand on their own."""
    spec = assembler.REGISTERED_ROBOTS[robot].spec
    return [*BASES, None] if spec.arm_type == "single" else [None]


COMBINATIONS = [
    (robot, base, gripper)
    for robot in ROBOTS
    for base, gripper in itertools.product(_sensible_bases(robot), [*GRIPPERS, None])
]

FREE = mujoco.mjtJoint.mjJNT_FREE


def test_every_kind_of_part_is_shipped() -> None:
    assert {"Sparrow7", "Finch6", "TwinTorso", "Biped", "BipedFree"} <= set(ROBOTS)
    morphologies = {assembler.REGISTERED_ROBOTS[name].spec.morphology for name in ROBOTS}
    assert {"manipulator", "humanoid"} <= morphologies
    types = {assembler.REGISTERED_BASES[name].spec.type for name in BASES}
    assert types == {"mount", "mobile", "legged", "null"}
    assert {"PincerGripper", "TriHand", "BareFlange"} <= set(GRIPPERS)


@pytest.mark.parametrize("name", ROBOTS)
def test_shipped_robot_round_trips_through_xml(name: str) -> None:
    robot = assembler.assemble(name, idn=0)
    model = robot.get_model()
    reloaded = mujoco.MjModel.from_xml_string(robot.get_xml())
    assert (reloaded.nq, reloaded.nv, reloaded.nu, reloaded.nbody) == (
        model.nq,
        model.nv,
        model.nu,
        model.nbody,
    )
    np.testing.assert_allclose(reloaded.dof_armature, model.dof_armature)
    np.testing.assert_allclose(reloaded.dof_damping, model.dof_damping)
    np.testing.assert_allclose(reloaded.body_mass, model.body_mass)
    np.testing.assert_allclose(reloaded.key_qpos, model.key_qpos)


def _with_floor(robot: assembler.RobotModel) -> mujoco.MjModel:
    robot.set_base_xpos(np.zeros(3))
    robot.mjspec.worldbody.add_geom(name="test_floor", type=mujoco.mjtGeom.mjGEOM_PLANE, size=[5, 5, 0.1])
    return robot.get_model()


def _self_contacts(model: mujoco.MjModel, data: mujoco.MjData) -> list[tuple[str, str]]:
    floor = model.geom("test_floor").id
    pairs = [(c.geom1, c.geom2) for c in data.contact[: data.ncon]]
    return [
        (model.body(model.geom_bodyid[a]).name, model.body(model.geom_bodyid[b]).name)
        for a, b in pairs
        if floor not in (a, b)
    ]


@pytest.mark.parametrize(("robot_name", "base", "gripper"), COMBINATIONS)
def test_combination_holds_its_home_pose_for_one_second(
    robot_name: str, base: str | None, gripper: str | None
) -> None:
    arms = assembler.REGISTERED_ROBOTS[robot_name].spec.arms
    robot = assembler.assemble(robot_name, idn=0, base=base, grippers=dict.fromkeys(arms, gripper))
    model = _with_floor(robot)
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    mujoco.mj_forward(model, data)
    assert _self_contacts(model, data) == [], "parts touch each other at the home pose"
    joints = [j for j in range(model.njnt) if model.jnt_type[j] != FREE]
    addresses = model.jnt_qposadr[joints]
    home = data.qpos[addresses].copy()
    height = data.xpos[model.body(robot.root_body).id][2]
    for _ in range(int(round(1.0 / model.opt.timestep))):
        mujoco.mj_step(model, data)
    assert np.all(np.isfinite(data.qpos)) and np.all(np.isfinite(data.qvel))
    drift = np.abs(data.qpos[addresses] - home)
    worst = model.joint(joints[int(np.argmax(drift))]).name
    assert drift.max() < 0.05, f"{worst} drifts {drift.max():.3f} from home in 1 s"
    assert abs(data.xpos[model.body(robot.root_body).id][2] - height) < 0.03, "the robot sinks or falls"
