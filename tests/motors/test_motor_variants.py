"""A variant of a motor-driven robot patched onto its compiled model equals its full compile: the
variant's joint values are resolved with its motors, whatever the override changes."""

from __future__ import annotations

import copy
from typing import Any

import numpy as np
import pytest

import assembler
from assembler.patch.derived import apply_patch
from assembler.patch.patchable import model_patch
from assembler.patch.resolved import Resolved, resolve_variant
from assembler.spec.documents import parse_overrides
from tests.conftest import TWO_LINK_MJCF
from tests.motors.rigs import MOTOR, Write, motor_yaml

ROBOT = """\
name: MotorArm
mjcf: twolink.xml
motors:
  - {match: shoulder, motor: TestMotor, control: torque}
"""
"""The two-link arm, its shoulder driven by the test motor, its elbow by the file's servo."""

CASES: list[dict[str, Any]] = [
    {"joint_defaults.damping": 0.35},
    {"joint_defaults.armature": {"inverse_index": 2.0}},
    {"joints": [{"match": "elbow", "armature": 0.4}]},
]


@pytest.mark.parametrize("overrides", CASES, ids=[next(iter(case)) for case in CASES])
def test_a_patched_variant_of_a_motor_driven_robot_equals_its_full_compile(
    write: Write, overrides: dict[str, Any]
) -> None:
    write("m/twolink.xml", TWO_LINK_MJCF)
    assembler.register_specs(write("m/motor.yaml", motor_yaml()), write("m/robot.yaml", ROBOT))
    base = assembler.assemble("MotorArm")
    model = base.get_model(cache=False, store=False)
    compiled = assembler.assemble("MotorArm", overrides=overrides).get_model(cache=False, store=False)
    resolved = Resolved.of(base)
    patched = copy.copy(model)
    apply_patch(
        patched, model_patch(model, resolved, resolve_variant(base, resolved, parse_overrides(overrides)))
    )
    shoulder = compiled.joint(base.naming_prefix + "shoulder")
    assert shoulder.armature[0] == pytest.approx(MOTOR["rotor_inertia"] * MOTOR["gear_ratio"] ** 2)
    for field in (
        "dof_armature",
        "dof_damping",
        "dof_frictionloss",
        "actuator_forcerange",
        "actuator_gainprm",
    ):
        assert np.allclose(getattr(patched, field), getattr(compiled, field), rtol=1e-12, atol=0), field


MOTOR_CASES: list[tuple[str, dict[str, Any]]] = [
    ("torque", {"motors[0].gear_ratio": 36}),
    ("position, kp: 40, dampratio: 1", {"motors[0].gear_ratio": 20, "motors[0].efficiency": 0.7}),
    ("voltage", {"motors[0].gear_ratio": 25}),
    ("voltage, voltage_actuator: general", {"motors[0].efficiency": 0.6}),
]


@pytest.mark.parametrize(("control", "overrides"), MOTOR_CASES, ids=[c for c, _ in MOTOR_CASES])
def test_a_variant_of_a_motor_gearbox_is_patched_and_equals_its_full_compile(
    write: Write, control: str, overrides: dict[str, Any]
) -> None:
    write("m/twolink.xml", TWO_LINK_MJCF)
    robot = ROBOT.replace("control: torque", f"control: {control}")
    assembler.register_specs(write("m/motor.yaml", motor_yaml()), write("m/robot.yaml", robot))
    base = assembler.assemble("MotorArm")
    model = base.get_model(cache=False, store=False)
    compiled = assembler.assemble("MotorArm", overrides=overrides).get_model(cache=False, store=False)
    resolved = Resolved.of(base)
    patch = model_patch(model, resolved, resolve_variant(base, resolved, parse_overrides(overrides)))
    patched = copy.copy(model)
    apply_patch(patched, patch)
    assert patch.fields, "the variant changed nothing"
    for name in dir(compiled):
        theirs = getattr(compiled, name, None)
        if isinstance(theirs, np.ndarray) and theirs.dtype != object:
            ours = getattr(patched, name)
            assert np.allclose(ours, theirs, rtol=1e-10, atol=1e-12, equal_nan=True), name
