"""Every shipped spec validates, builds, compiles, holds its home pose and simulates without NaN.

New specs are tested by being added to ``specs/``: nobody has to write a test for them.
"""

from __future__ import annotations

import mujoco
import numpy as np
import pytest

import assembler
from assembler.loader import load_paths, spec_files
from assembler.paths import shipped_specs_dir

SHIPPED = [loaded.spec.name for loaded in load_paths([shipped_specs_dir()])]


def test_there_are_shipped_robots_of_our_own() -> None:
    assert {"Sparrow7", "Finch6"} <= set(SHIPPED)
    assert spec_files(shipped_specs_dir())


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_robot_compiles_and_round_trips_through_xml(name: str) -> None:
    robot = assembler.create_robot(name, idn=0)
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


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_robot_holds_its_home_pose_for_one_second(name: str) -> None:
    robot = assembler.create_robot(name, idn=0)
    model = robot.get_model()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    home = data.qpos.copy()
    mujoco.mj_forward(model, data)
    assert data.ncon == 0, "links touch each other at the home pose"
    steps = int(round(1.0 / model.opt.timestep))
    for _ in range(steps):
        mujoco.mj_step(model, data)
    assert np.all(np.isfinite(data.qpos)) and np.all(np.isfinite(data.qvel))
    assert np.max(np.abs(data.qpos - home)) < 0.05, "the actuators do not hold the home pose"


@pytest.mark.parametrize("name", SHIPPED)
def test_shipped_robot_is_plausible(name: str) -> None:
    robot = assembler.create_robot(name, idn=0)
    model = robot.get_model()
    assert robot.dof == model.njnt - int(np.sum(model.jnt_type == mujoco.mjtJoint.mjJNT_FREE))
    assert 1.0 < float(np.sum(model.body_mass)) < 200.0
    assert np.all(model.jnt_limited[model.jnt_type == mujoco.mjtJoint.mjJNT_HINGE])
