"""Actuators declared in a spec: a URDF has none, and an MJCF's may not be the ones an experiment wants.

Each entry drives the joints whose names match (an exact name or a glob, as in ``joints:``) with one
actuator per joint. Ranges left out come from the joint: a position servo's ``ctrlrange`` is the
joint's range, a velocity servo's the URDF's velocity limit, a motor's the joint's effort limit
(divided by the gear); ``forcerange`` is the joint's effort limit. With ``force: false`` a joint
that already has an actuator in the file keeps it.
"""

from __future__ import annotations

from typing import Annotated, Literal

from pydantic import Field, model_validator

from assembler.spec.schema.common import FiniteFloat, NonNegativeFloat, Range, StrictModel, rule_error

ActuatorType = Literal["position", "velocity", "motor", "general"]

Parameters = Annotated[list[FiniteFloat], Field(min_length=1, max_length=10)]
"""Up to ten numbers: MuJoCo's gainprm or biasprm."""

GAINS_OF: dict[str, tuple[str, ...]] = {
    "position": ("kp", "kv", "dampratio"),
    "velocity": ("kv",),
    "motor": (),
    "general": ("gainprm", "biasprm"),
}
"""The gain fields each actuator type takes."""

GAIN_FIELDS: tuple[str, ...] = ("kp", "kv", "dampratio", "gainprm", "biasprm")

REQUIRED_GAIN: dict[str, str] = {"position": "kp", "velocity": "kv", "general": "gainprm"}


class ActuatorDeclaration(StrictModel):
    """One actuator on each joint whose name matches."""

    match: str = Field(min_length=1)
    """A joint name as written in the file (without prefix) or a glob such as 'panda_joint*'; globs skip
    joints that follow another through a joint equality (URDF `<mimic>`)."""

    type: ActuatorType = "position"
    """position (kp, kv or dampratio), velocity (kv), motor (force or torque), general (gainprm, biasprm)."""

    name: str = Field(default="{joint}", min_length=1, pattern=r"^[A-Za-z0-9_{}\-.]+$")
    """The actuator's name; '{joint}' becomes the joint's name (actuator and joint names never clash)."""

    kp: NonNegativeFloat | None = None
    """Position gain (N m/rad or N/m) of a position servo."""

    kv: NonNegativeFloat | None = None
    """Velocity gain: of a velocity servo, or the damping of a position servo (N m s/rad or N s/m)."""

    dampratio: NonNegativeFloat | None = None
    """Damping of a position servo as a ratio of critical damping (1: critically damped), instead of kv."""

    gainprm: Parameters | None = None
    """MuJoCo's gainprm of a general actuator (force = gain * ctrl + bias)."""

    biasprm: Parameters | None = None
    """MuJoCo's biasprm of a general actuator (affine bias: b0 + b1 * qpos + b2 * qvel); none for no bias."""

    gear: FiniteFloat = Field(default=1.0)
    """Transmission ratio: the joint receives gear times the actuator's force."""

    ctrlrange: Range | None = None
    """Range of the control; null takes it from the joint (position range, velocity or effort limit)."""

    forcerange: Range | None = None
    """Range of the actuator's force; null takes the joint's effort limit (URDF `<limit effort>`), if any."""

    force: bool = True
    """If false, joints that already have an actuator in the file keep it and get none from this entry."""

    @model_validator(mode="after")
    def _gains_fit_the_type(self) -> ActuatorDeclaration:
        allowed = GAINS_OF[self.type]
        given = [
            name
            for name in ("kp", "kv", "dampratio", "gainprm", "biasprm")
            if getattr(self, name) is not None
        ]
        foreign = [name for name in given if name not in allowed]
        if foreign:
            takes = ", ".join(allowed) if allowed else "no gains"
            raise rule_error(f"a {self.type} actuator takes {takes}, not {foreign[0]}")
        required = REQUIRED_GAIN.get(self.type)
        if required is not None and required not in given:
            raise rule_error(f"a {self.type} actuator needs {required}")
        if self.kv is not None and self.dampratio is not None:
            raise rule_error("give kv or dampratio, not both")
        if self.gear == 0:
            raise rule_error("gear must not be 0")
        return self
