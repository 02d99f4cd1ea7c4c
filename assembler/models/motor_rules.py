"""What a motor and its gearbox give the joint they drive, each value with its formula and numbers.

With N the gear ratio (motor turns per joint turn) and η the gearbox efficiency:

- armature ``rotor_inertia × N² (+ gearbox_inertia)``: the rotor's inertia seen at the joint;
- frictionloss ``friction_torque × N`` and damping ``viscous_friction × N²``;
- the torque limit ``(peak_torque or stall_torque) × N × η``, the stall torque being ``kt × V / R``
  where the datasheet gives the constants but not the torque;
- for ``control: voltage``, the DC motor at the joint ``τ = N·η·kt·(V − kt·N·ω)/R``.

Ratings an integrated actuator's datasheet gives at its output (``ratings_at: output``) are taken
back to the motor shaft through the spec's own gearbox, then out through the entry's. Nothing is
derived from a value the motor spec leaves out.
"""

from __future__ import annotations

from dataclasses import dataclass

from assembler.spec.schema import JointMotor, MotorSpec


@dataclass(frozen=True)
class Derived:
    """A value derived from a motor spec: the value, its formula in the spec's words, and its numbers."""

    value: float
    formula: str
    """E.g. ``rotor_inertia × gear_ratio²``."""

    numbers: str
    """The formula with the spec's numbers, e.g. ``1.12e-05 kg·m² × 29.5²``."""

    def __str__(self) -> str:
        return f"{self.value:.6g} = {self.numbers}"


@dataclass(frozen=True)
class VoltageModel:
    """The constants of ``control: voltage``: torque constant, resistance, voltage (at the motor)."""

    torque_constant: Derived
    resistance: Derived
    voltage: float


def _g(value: float) -> str:
    return f"{value:.6g}"


@dataclass(frozen=True)
class Drive:
    """A motor spec with the gearbox one ``motors:`` entry gives it."""

    motor: MotorSpec
    entry: JointMotor
    index: int
    """The entry's index in ``motors:``."""

    @property
    def gear_ratio(self) -> float:
        """N: the entry's gear ratio, else the motor spec's."""
        return self.entry.gear_ratio if self.entry.gear_ratio is not None else self.motor.gear_ratio

    @property
    def efficiency(self) -> float:
        """η: the entry's efficiency, else the motor spec's."""
        return self.entry.efficiency if self.entry.efficiency is not None else self.motor.efficiency

    @property
    def own_gearbox(self) -> bool:
        """Whether the joint sees the motor spec's own gearbox (its output ratings apply as given)."""
        return self.gear_ratio == self.motor.gear_ratio and self.efficiency == self.motor.efficiency

    def _output_torque(self, field: str, value: float, efficiency: bool = True) -> Derived:
        """A torque rating at the joint: ``value × N (× η)`` from the motor shaft, or from the output of
        the spec's gearbox through the entry's."""
        n, eta = self.gear_ratio, self.efficiency if efficiency else 1.0
        eta_text = " × efficiency" if efficiency else ""
        eta_numbers = f" × {_g(eta)}" if efficiency else ""
        if self.motor.ratings_at == "motor":
            return Derived(
                value * n * eta, f"{field} × gear_ratio{eta_text}", f"{_g(value)} N·m × {_g(n)}{eta_numbers}"
            )
        if self.own_gearbox:
            return Derived(value, f"{field} (at the actuator's output)", f"{_g(value)} N·m at the output")
        n0, eta0 = self.motor.gear_ratio, self.motor.efficiency if efficiency else 1.0
        return Derived(
            value * n * eta / (n0 * eta0),
            f"{field} / (spec gear_ratio{eta_text}) × gear_ratio{eta_text}",
            f"{_g(value)} N·m / ({_g(n0)}{f' × {_g(eta0)}' if efficiency else ''}) × {_g(n)}{eta_numbers}",
        )

    def armature(self) -> Derived | None:
        """``rotor_inertia × N²``, plus the spec's gearbox_inertia when the joint sees that gearbox."""
        motor, n = self.motor, self.gear_ratio
        if motor.rotor_inertia is None:
            return None
        value = motor.rotor_inertia * n**2
        formula, numbers = "rotor_inertia × gear_ratio²", f"{_g(motor.rotor_inertia)} kg·m² × {_g(n)}²"
        if motor.gearbox_inertia and self.gear_ratio == motor.gear_ratio:
            value += motor.gearbox_inertia
            formula += " + gearbox_inertia"
            numbers += f" + {_g(motor.gearbox_inertia)} kg·m²"
        return Derived(value, formula, numbers)

    def frictionloss(self) -> Derived | None:
        """``friction_torque × N``."""
        if self.motor.friction_torque is None:
            return None
        return self._output_torque("friction_torque", self.motor.friction_torque, efficiency=False)

    def damping(self) -> Derived | None:
        """``viscous_friction × N²``."""
        motor, n = self.motor, self.gear_ratio
        if motor.viscous_friction is None:
            return None
        if motor.ratings_at == "motor":
            return Derived(
                motor.viscous_friction * n**2,
                "viscous_friction × gear_ratio²",
                f"{_g(motor.viscous_friction)} N·m·s/rad × {_g(n)}²",
            )
        n0 = motor.gear_ratio
        if n == n0:
            value = motor.viscous_friction
            return Derived(value, "viscous_friction (at the actuator's output)", f"{_g(value)} N·m·s/rad")
        return Derived(
            motor.viscous_friction * (n / n0) ** 2,
            "viscous_friction × (gear_ratio / spec gear_ratio)²",
            f"{_g(motor.viscous_friction)} N·m·s/rad × ({_g(n)} / {_g(n0)})²",
        )

    def stall_torque(self) -> Derived | None:
        """The stall torque at the joint: the datasheet's, else ``kt × V / R`` at the motor times N × η."""
        motor = self.motor
        if motor.stall_torque is not None:
            return self._output_torque("stall_torque", motor.stall_torque)
        kt, resistance, voltage = motor.torque_constant, motor.resistance, motor.voltage
        if kt is None or resistance is None or voltage is None:
            return None
        n, eta = self.gear_ratio, self.efficiency
        return Derived(
            n * eta * kt * voltage / resistance,
            "gear_ratio × efficiency × torque_constant × voltage / resistance",
            f"{_g(n)} × {_g(eta)} × {_g(kt)} N·m/A × {_g(voltage)} V / {_g(resistance)} Ω",
        )

    def torque_limit(self) -> Derived | None:
        """The largest joint torque: ``peak_torque × N × η``, else the stall torque at the joint."""
        if self.motor.peak_torque is not None:
            return self._output_torque("peak_torque", self.motor.peak_torque)
        return self.stall_torque()

    def no_load_speed(self) -> Derived | None:
        """The joint's speed without load at the nominal voltage: ``V / (kt × N)``."""
        voltage = self.voltage_model()
        if voltage is None:
            return None
        kt, n = voltage.torque_constant.value, self.gear_ratio
        return Derived(
            voltage.voltage / (kt * n),
            "voltage / (torque_constant × gear_ratio)",
            f"{_g(voltage.voltage)} V / ({_g(kt)} N·m/A × {_g(n)})",
        )

    def voltage_model(self) -> VoltageModel | None:
        """kt and R at the motor: the datasheet's, else from its (voltage, stall torque, no-load speed)
        triple, as MuJoCo's ``nominal`` does (``kt = V / ω₀``, ``R = kt × V / τ_stall``); None without
        a voltage or without enough values."""
        motor = self.motor
        if motor.voltage is None:
            return None
        voltage = motor.voltage
        if motor.torque_constant is not None and motor.resistance is not None:
            kt = Derived(motor.torque_constant, "torque_constant", f"{_g(motor.torque_constant)} N·m/A")
            resistance = Derived(motor.resistance, "resistance", f"{_g(motor.resistance)} Ω")
            return VoltageModel(kt, resistance, voltage)
        if motor.stall_torque is None or motor.no_load_speed is None:
            return None
        speed, torque = motor.no_load_speed, motor.stall_torque
        at_output = motor.ratings_at == "output"
        n0, eta0 = motor.gear_ratio, motor.efficiency
        shaft_speed = speed * n0 if at_output else speed
        shaft_torque = torque / (n0 * eta0) if at_output else torque
        kt_value = voltage / shaft_speed
        speed_text = f"({_g(speed)} rad/s × {_g(n0)})" if at_output else f"{_g(speed)} rad/s"
        torque_text = f"({_g(torque)} N·m / ({_g(n0)} × {_g(eta0)}))" if at_output else f"{_g(torque)} N·m"
        kt = Derived(kt_value, "voltage / no_load_speed at the motor", f"{_g(voltage)} V / {speed_text}")
        resistance = Derived(
            kt_value * voltage / shaft_torque,
            "torque_constant × voltage / stall_torque at the motor",
            f"{_g(kt_value)} N·m/A × {_g(voltage)} V / {torque_text}",
        )
        return VoltageModel(kt, resistance, voltage)

    def voltage_derivations(self, model: VoltageModel) -> tuple[tuple[str, Derived], ...]:
        """What ``control: voltage`` sets and gives at the joint, by name: kt and R, the actuator's
        parameters, the no-load speed ``V/(kt·N)`` and the stall torque ``N·η·kt·V/R``."""
        n, eta, voltage = self.gear_ratio, self.efficiency, model.voltage
        kt, resistance = model.torque_constant.value, model.resistance.value
        constants = (("torque_constant", model.torque_constant), ("resistance", model.resistance))
        found = [(name, derived) for name, derived in constants if derived.formula != name]  # derived ones
        if self.entry.voltage_actuator == "general":
            gain = Derived(
                n * eta * kt / resistance,
                "gear_ratio × efficiency × kt / R",
                f"{_g(n)} × {_g(eta)} × {_g(kt)} / {_g(resistance)}",
            )
            slope = Derived(
                -(n**2) * eta * kt**2 / resistance,
                "-gear_ratio² × efficiency × kt² / R",
                f"-{_g(n)}² × {_g(eta)} × {_g(kt)}² / {_g(resistance)}",
            )
            found += [("gainprm[0]", gain), ("biasprm[2]", slope)]
        else:
            found.append(
                (
                    "dcmotor resistance",
                    Derived(resistance / eta, "R / efficiency", f"{_g(resistance)} / {_g(eta)}"),
                )
            )
        speed = Derived(
            voltage / (kt * n), "voltage / (kt × gear_ratio)", f"{_g(voltage)} / ({_g(kt)} × {_g(n)})"
        )
        stall = Derived(
            n * eta * kt * voltage / resistance,
            "gear_ratio × efficiency × kt × voltage / R",
            f"{_g(n)} × {_g(eta)} × {_g(kt)} × {_g(voltage)} / {_g(resistance)}",
        )
        return (*found, ("no-load speed", speed), ("stall torque", stall))
