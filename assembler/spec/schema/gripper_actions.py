"""How a gripper turns a policy's actions into actuator controls (robosuite's ``format_action``).

Each action dimension drives one or more actuators, each with a direction (+1 or -1). In the
incremental mode (robosuite's two-finger grippers) every output keeps a state that an action moves
by ``speed`` towards +1 or -1; in the absolute mode (robosuite's dexterous hands) an action is the
output itself. Outputs are in [-1, 1]; robosuite's GRIP controller maps them onto each actuator's
ctrlrange. Held actuators get a constant output (robosuite's Robotiq three-finger scissor).
"""

from __future__ import annotations

from typing import Literal

from pydantic import Field, model_validator

from assembler.spec.schema.common import FiniteFloat, StrictModel


class GripperAction(StrictModel):
    """One action dimension: the actuators it drives and in which direction."""

    actuators: list[str] = Field(min_length=1)
    """Actuator names as written in the gripper's MJCF (without its prefix)."""

    direction: list[Literal[-1, 1]] | None = None
    """Per actuator, +1 (the action's sign moves the control towards its high end) or -1; null: all +1."""

    @model_validator(mode="after")
    def _one_direction_per_actuator(self) -> GripperAction:
        if self.direction is not None and len(self.direction) != len(self.actuators):
            raise ValueError(
                f"direction has {len(self.direction)} values for {len(self.actuators)} actuators; "
                "give one each"
            )
        return self

    def directions(self) -> list[int]:
        """The direction of each actuator (+1 where none is given)."""
        return list(self.direction) if self.direction is not None else [1] * len(self.actuators)


ActionMode = Literal["incremental", "absolute"]
"""incremental: each action moves a kept output by ``speed``; absolute: the action is the output."""

ActionInput = Literal["sign", "value"]
"""sign: only an action's sign counts (robosuite's two-finger grippers); value: its value."""


class GripperActions(StrictModel):
    """How a policy's gripper actions become actuator outputs (robosuite's format_action): outputs are in
    [-1, 1], and robosuite's gripper controller maps each onto its actuator's ctrlrange."""

    dimensions: list[GripperAction] = Field(default_factory=list)
    """One entry per action dimension, in order; the gripper's dof is their number."""

    mode: ActionMode = "incremental"
    """incremental: every step moves each output by the gripper's speed in its action's direction, so
    fingers keep closing while the action says close (robosuite's two-finger grippers); absolute: the action
    is the output (robosuite's dexterous hands)."""

    reads: ActionInput | None = None
    """How an action is read: sign (only whether it is positive or negative counts) or value; null: sign
    when incremental, value when absolute."""

    hold: dict[str, FiniteFloat] = Field(default_factory=dict)
    """Actuators held at a constant output in [-1, 1], driven by no action (e.g. the scissor joint of
    robosuite's Robotiq three-finger gripper); actuators neither driven nor held output 0."""

    @model_validator(mode="after")
    def _each_actuator_once(self) -> GripperActions:
        named = [name for action in self.dimensions for name in action.actuators] + list(self.hold)
        twice = sorted({name for name in named if named.count(name) > 1})
        if twice:
            raise ValueError(f"actuator {twice[0]} is driven twice; give each actuator to one action or hold")
        return self

    def reading(self) -> ActionInput:
        """How actions are read (the default chosen by the mode)."""
        if self.reads is not None:
            return self.reads
        return "value" if self.mode == "absolute" else "sign"
