"""A voltage-controlled joint in a MuJoCo Warp batch behaves as the datasheet's DC motor in every world:
a plan varies the gearbox (ratio and efficiency), each world is driven at its own voltage, and each
reaches its own no-load speed ``V/(kt·N)`` and, held, delivers its own stall torque ``N·η·kt·V/R``
within 1%, with MuJoCo's native ``dcmotor`` (what a spec gets by default, and what MuJoCo Warp runs)
and with its ``general`` equivalent."""

from __future__ import annotations

from collections.abc import Iterator

import mujoco
import numpy as np
import pytest
from numpy.typing import NDArray

pytest.importorskip("mujoco_warp", reason="MuJoCo Warp is not installed: pip install -e '.[warp]'")

import mujoco_warp  # noqa: E402

from assembler.models.motor_table import MOTORS  # noqa: E402
from assembler.warp import WarpBatch, put_variants  # noqa: E402
from assembler.worlds.variants.plan import Grid, VariantPlan  # noqa: E402
from tests.motors.rigs import MOTOR, Write, motor_robot  # noqa: E402

PLAN = VariantPlan(
    "Spinner",
    grids=(Grid.parse("motors[0].gear_ratio=5,20"), Grid.parse("motors[0].efficiency=0.6,0.9")),
)
"""Four spinner worlds: gear ratios 5 and 20, each behind a gearbox passing 60% and 90% of the torque."""

VOLTAGES = MOTOR["voltage"] * np.array([1.0, -0.5, 0.75, 0.25])
"""Each world's voltage at the terminals (within the motor's ±voltage ctrlrange), one per world."""

KINDS = ("dcmotor", "general")
GAINTYPES = {"dcmotor": mujoco.mjtGain.mjGAIN_DCMOTOR, "general": mujoco.mjtGain.mjGAIN_FIXED}


@pytest.fixture(autouse=True)
def isolated_motors() -> Iterator[None]:
    """The test motor spec is forgotten afterwards (the shipped ones stay)."""
    before = MOTORS.state()
    yield
    MOTORS.restore(before)


def _batch(write: Write, kind: str, joint_extra: str = "") -> WarpBatch:
    entry = f"{{match: spin, motor: TestMotor, control: voltage, voltage_actuator: {kind}}}"
    motor_robot(write, entry, joint_extra=joint_extra)
    batch = put_variants(PLAN)
    assert batch.nworld == len(VOLTAGES)
    assert batch.cpu_model.actuator_gaintype[0] == GAINTYPES[kind]  # what the spec compiles to ...
    assert batch.model.actuator_gaintype.numpy()[0] == GAINTYPES[kind]  # ... is what MuJoCo Warp runs
    return batch


def _gearboxes(batch: WarpBatch) -> tuple[NDArray[np.float64], NDArray[np.float64]]:
    """Each world's gear ratio and efficiency, as its variant says."""
    variants = [batch.variant(world) for world in range(batch.nworld)]
    ratios = np.array([v["motors[0].gear_ratio"] for v in variants], dtype=float)
    efficiencies = np.array([v["motors[0].efficiency"] for v in variants], dtype=float)
    assert len(set(zip(ratios, efficiencies, strict=True))) == batch.nworld  # every world differs
    return ratios, efficiencies


def _run(batch: WarpBatch, seconds: float) -> None:
    batch.data.ctrl.assign(VOLTAGES.reshape(-1, 1).astype(np.float32))
    for _ in range(round(seconds / float(batch.cpu_model.opt.timestep))):
        mujoco_warp.step(batch.model, batch.data)


@pytest.mark.parametrize("kind", KINDS)
def test_every_world_without_load_reaches_its_own_no_load_speed(write: Write, kind: str) -> None:
    batch = _batch(write, kind)
    ratios, efficiencies = _gearboxes(batch)
    kt, resistance = MOTOR["torque_constant"], MOTOR["resistance"]
    # the slowest world's mechanical time constant (joint inertia / back-EMF damping): 0.25 s is 20 of them
    inertia = batch.cpu_model.body_inertia[batch.cpu_model.body("robot0_rotor").id][2]
    armature = MOTOR["rotor_inertia"] * ratios**2
    tau = (inertia + armature) / (ratios**2 * efficiencies * kt**2 / resistance)
    assert 20 * tau.max() < 0.25
    np.testing.assert_allclose(batch.model.dof_armature.numpy()[:, 0], armature, rtol=1e-6)
    _run(batch, 0.25)
    np.testing.assert_allclose(batch.data.qvel.numpy()[:, 0], VOLTAGES / (kt * ratios), rtol=0.01)


@pytest.mark.parametrize("kind", KINDS)
def test_every_world_held_still_delivers_its_own_stall_torque(write: Write, kind: str) -> None:
    batch = _batch(write, kind, joint_extra=' range="-0.001 0.001"')  # the joint limit holds it
    ratios, efficiencies = _gearboxes(batch)
    _run(batch, 0.5)
    kt, resistance = MOTOR["torque_constant"], MOTOR["resistance"]
    stall = ratios * efficiencies * kt * VOLTAGES / resistance
    assert np.abs(batch.data.qvel.numpy()[:, 0]).max() < 1e-3
    np.testing.assert_allclose(batch.data.qfrc_actuator.numpy()[:, 0], stall, rtol=0.01)
