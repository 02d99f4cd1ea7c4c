"""A gripper's declared actions (``actions:`` in its spec) as robosuite's ``format_action``.

The outputs are in the gripper's actuator order, each in [-1, 1]. In the incremental mode each
output keeps a state (robosuite's ``current_action``) that every action moves by ``speed`` in its
direction; in the absolute mode the action is the output. Checked against all 16 of robosuite's
grippers (``tests/robosuite/test_gripper_actions.py``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np
from numpy.typing import NDArray

if TYPE_CHECKING:  # the spec's type only: a recorded gripper's map is rebuilt without the schema
    from assembler.spec.schema.gripper_actions import GripperActions

FloatArray = NDArray[np.float64]


@dataclass(frozen=True)
class ActionMap:
    """Which action drives each actuator output, with which sign, and the held outputs."""

    dof: int
    """Number of action values the gripper takes."""

    source: NDArray[np.int64]
    """Per actuator, the index of the action driving it; -1 for held (or undriven) ones."""

    sign: FloatArray
    """Per actuator, +1 or -1: the direction an action's sign moves it."""

    held: FloatArray
    """Per actuator, the constant output of a held (or undriven) actuator."""

    speed: float
    """How far one incremental action moves an output."""

    incremental: bool
    """True: outputs keep a state that actions move; False: the action is the output."""

    by_sign: bool
    """True: only an action's sign counts; False: its value."""

    @classmethod
    def of(cls, actions: GripperActions, actuators: Sequence[str], speed: float) -> ActionMap:
        """The map of ``actions`` onto the gripper's ``actuators`` (MJCF names, in order); names are
        checked against the MJCF when the gripper is validated."""
        index = {name: i for i, name in enumerate(actuators)}
        source = np.full(len(actuators), -1, dtype=np.int64)
        sign, held = np.ones(len(actuators)), np.zeros(len(actuators))
        for number, action in enumerate(actions.dimensions):
            for name, direction in zip(action.actuators, action.directions(), strict=True):
                source[index[name]], sign[index[name]] = number, direction
        for name, value in actions.hold.items():
            held[index[name]] = value
        incremental = actions.mode == "incremental"
        return cls(
            len(actions.dimensions), source, sign, held, speed, incremental, actions.reading() == "sign"
        )

    def format_action(self, action: Sequence[float], state: FloatArray) -> tuple[FloatArray, FloatArray]:
        """The outputs for ``action`` given the kept ``state``; returns (outputs, the new state)."""
        values = np.asarray(action, dtype=float).ravel()
        if values.size != self.dof:
            raise ValueError(f"the gripper takes {self.dof} action values, got {values.size}")
        if self.dof == 0:
            return values, state
        read = np.sign(values) if self.by_sign else values
        driven = self.source >= 0
        pushed = read[np.maximum(self.source, 0)] * self.sign
        if not self.incremental:
            return np.where(driven, pushed, self.held), state
        # robosuite resets the state to zeros(dof), which then broadcasts onto the outputs
        current = state if state.shape == self.source.shape else np.zeros(self.source.shape)
        outputs = np.where(driven, np.clip(current + self.speed * pushed, -1.0, 1.0), self.held)
        return outputs, outputs
