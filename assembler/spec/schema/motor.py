"""Motors: a motor spec (a datasheet's values in SI units, with its source) and the ``motors:``
entries of a part spec that put motors on its joints.

A motor spec describes a motor with a gearbox, or an integrated actuator (a servo, a quasi-direct
drive) with both; a ``motors:`` entry may give its own gearbox, which replaces the spec's (one motor,
several gearboxes). What each value becomes in MuJoCo is derived in :mod:`assembler.models.motor_rules`
and documented in docs/motors.md.
"""

from __future__ import annotations

from typing import Annotated, Any, Literal

from pydantic import Field, ValidationInfo, field_validator, model_validator

from assembler.spec.schema.common import NOT_BOOL, Name, NonNegativeFloat, StrictModel, rule_error

PositiveFloat = Annotated[float, Field(gt=0.0, allow_inf_nan=False), NOT_BOOL]
"""A finite number larger than zero (NOT_BOOL after the Field: before it, pydantic's JSON Schema writes the
bound as "gt", which no editor reads, instead of "exclusiveMinimum")."""

Efficiency = Annotated[float, Field(gt=0.0, le=1.0, allow_inf_nan=False), NOT_BOOL]
"""A fraction of the power that passes, above 0 and at most 1."""

Control = Literal["voltage", "torque", "position"]
"""What a motor-driven joint's ``ctrl`` is: volts at the terminals, joint torque, or a target position."""

VoltageActuator = Literal["dcmotor", "general"]
"""How ``control: voltage`` is modelled: MuJoCo's own DC motor, or the exact ``general`` equivalent of
its basic form."""


class MotorSpec(StrictModel):
    """A motor (with or without its gearbox) or an integrated actuator, from its datasheet.

    Values are at the motor shaft, except the torques, speeds and frictions of an integrated actuator
    whose datasheet gives them at its output (``ratings_at: output``). Leave out what the datasheet
    does not give: nothing is derived from a value that is not there."""

    kind: Literal["motor"]
    """Marks a motor spec."""

    name: Name
    """The name ``motors:`` entries use (``motor: NAME``)."""

    description: str = ""
    """One or two sentences for `assembler list` and the generated docs."""

    source: str = Field(min_length=1)
    """Where the values come from: the datasheet (title, revision, address) or the published constants."""

    voltage: PositiveFloat | None = None
    """Nominal supply voltage in volts (V): the ctrl range of ``control: voltage`` is ±voltage."""

    torque_constant: PositiveFloat | None = None
    """Torque per current at the motor shaft (N·m/A); in SI units also the back-EMF constant (V·s/rad)."""

    resistance: PositiveFloat | None = None
    """Terminal resistance in ohms (Ω), phase to phase for a brushless motor."""

    rotor_inertia: NonNegativeFloat | None = None
    """Moment of inertia of the rotor about its axis, at the motor shaft (kg·m²)."""

    inductance: NonNegativeFloat | None = None
    """Terminal inductance in henries (H); documented, not simulated (MuJoCo's basic DC motor has none)."""

    max_current: PositiveFloat | None = None
    """Largest current the motor or its driver allows, in amperes (A)."""

    gear_ratio: PositiveFloat = 1.0
    """Motor turns per output turn of the spec's own gearbox (1: none); a ``motors:`` entry may replace it."""

    efficiency: Efficiency = 1.0
    """Fraction of the motor's torque the gearbox passes to its output (1: lossless)."""

    gearbox_inertia: NonNegativeFloat | None = None
    """The gearbox's own inertia reflected to its output (kg·m²), added to the rotor's reflected inertia."""

    backlash: NonNegativeFloat | None = None
    """Free play of the gearbox at its output in radians (rad); documented, not simulated."""

    ratings_at: Literal["motor", "output"] = "motor"
    """Where stall_torque, peak_torque, no_load_speed, friction_torque and viscous_friction are given: at the
    motor shaft, or at the output of the spec's own gearbox (an integrated actuator's datasheet)."""

    tolerance: Annotated[float, Field(gt=0.0, lt=1.0), NOT_BOOL] = 0.1
    """How far (a fraction) stall_torque may differ from kt·V/R and no_load_speed from V/kt before the spec is
    refused: datasheets round, and measure at a temperature."""

    stall_torque: PositiveFloat | None = None
    """Torque at zero speed and the nominal voltage (N·m); checked against kt·voltage/resistance."""

    no_load_speed: PositiveFloat | None = None
    """Speed without load at the nominal voltage (rad/s); checked against voltage/torque_constant."""

    peak_torque: PositiveFloat | None = None
    """Largest torque the motor or actuator may give (N·m), e.g. at its driver's current limit."""

    friction_torque: NonNegativeFloat | None = None
    """Dry (Coulomb) friction torque (N·m): the joint's frictionloss."""

    viscous_friction: NonNegativeFloat | None = None
    """Viscous friction (N·m·s/rad): the joint's damping."""

    @field_validator("stall_torque")
    @classmethod
    def _stall_torque_fits_the_constants(cls, value: float | None, info: ValidationInfo) -> float | None:
        constants = _constants(info.data)
        if value is None or constants is None:
            return value
        kt, resistance, voltage, ratio, efficiency = constants
        expected = ratio * efficiency * kt * voltage / resistance
        formula = f"torque_constant × voltage / resistance = {kt:g} × {voltage:g} / {resistance:g}"
        if info.data.get("ratings_at") == "output":
            formula = (
                "gear_ratio × efficiency × torque_constant × voltage / resistance = "
                f"{ratio:g} × {efficiency:g} × {kt:g} × {voltage:g} / {resistance:g}"
            )
        _check(value, expected, info.data, "N·m", formula)
        return value

    @field_validator("no_load_speed")
    @classmethod
    def _no_load_speed_fits_the_constants(cls, value: float | None, info: ValidationInfo) -> float | None:
        constants = _constants(info.data)
        if value is None or constants is None:
            return value
        kt, _, voltage, ratio, _ = constants
        expected = voltage / (kt * ratio)
        formula = f"voltage / torque_constant = {voltage:g} / {kt:g}"
        if info.data.get("ratings_at") == "output":
            formula = f"voltage / (torque_constant × gear_ratio) = {voltage:g} / ({kt:g} × {ratio:g})"
        _check(value, expected, info.data, "rad/s", formula)
        return value

    @model_validator(mode="after")
    def _output_ratings_need_a_gearbox(self) -> MotorSpec:
        if self.ratings_at == "output" and self.gear_ratio == 1.0:
            raise rule_error("ratings_at: output means after the spec's own gearbox; give its gear_ratio")
        return self


def _constants(data: dict[str, Any]) -> tuple[float, float, float, float, float] | None:
    """(kt, R, V, N, η) when the three electrical constants are given (N and η: the spec's gearbox
    where the ratings are at its output, else 1), else None."""
    kt, resistance, voltage = (data.get(k) for k in ("torque_constant", "resistance", "voltage"))
    if kt is None or resistance is None or voltage is None:
        return None
    if data.get("ratings_at") == "output":
        return kt, resistance, voltage, data.get("gear_ratio", 1.0), data.get("efficiency", 1.0)
    return kt, resistance, voltage, 1.0, 1.0


def _check(value: float, expected: float, data: dict[str, Any], unit: str, formula: str) -> None:
    tolerance = data.get("tolerance", 0.1)
    off = abs(value - expected) / expected
    if off > tolerance:
        raise rule_error(
            f"{value:g} {unit} contradicts {formula} = {expected:.4g} {unit} ({off:.0%} apart, tolerance "
            f"{tolerance:.0%}); correct the value or the constants, or give the datasheet's tolerance"
        )


class JointMotor(StrictModel):
    """A motor on each joint whose name matches: the joint's armature, friction, damping and actuator."""

    match: str = Field(min_length=1)
    """A joint name as written in the model file (without prefix) or a glob such as '*_hip_joint'."""

    motor: Name
    """The motor spec's name (shipped under specs/motors/, or in a spec folder of yours)."""

    gear_ratio: PositiveFloat | None = None
    """Motor turns per joint turn; null: the motor spec's own gearbox."""

    efficiency: Efficiency | None = None
    """Fraction of the motor's torque the gearbox passes to the joint; null: the motor spec's."""

    control: Control | None = "torque"
    """voltage: ctrl is volts (a DC motor); torque: ctrl is the joint torque, limited to ±(peak or stall
    torque)·N·η; position: a position servo with that force limit; null: no actuator (the joint's
    values only, the file's actuator stays)."""

    voltage_actuator: VoltageActuator = "dcmotor"
    """control: voltage only. dcmotor: MuJoCo's native DC motor (MuJoCo 3.9+, MuJoCo Warp); general: the exact
    equivalent of its basic form (gain N·η·kt/R, velocity bias -N²·η·kt²/R) for engines without it."""

    kp: NonNegativeFloat | None = None
    """control: position only. Position gain at the joint (N·m/rad)."""

    kv: NonNegativeFloat | None = None
    """control: position only. Velocity gain at the joint (N·m·s/rad)."""

    dampratio: NonNegativeFloat | None = None
    """control: position only. Damping as a ratio of critical damping, instead of kv."""

    name: str = Field(default="{joint}", min_length=1, pattern=r"^[A-Za-z0-9_{}\-.]+$")
    """The actuator's name; '{joint}' becomes the joint's name."""

    @model_validator(mode="after")
    def _gains_fit_the_control(self) -> JointMotor:
        given = [name for name in ("kp", "kv", "dampratio") if getattr(self, name) is not None]
        if self.control != "position" and given:
            raise rule_error(f"{given[0]} is a position servo's gain; control is {self.control}")
        if self.control == "position" and self.kp is None:
            raise rule_error("control: position needs kp")
        if self.kv is not None and self.dampratio is not None:
            raise rule_error("give kv or dampratio, not both")
        return self
