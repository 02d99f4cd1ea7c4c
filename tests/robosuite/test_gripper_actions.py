"""A gripper's declared actions drive its actuators as robosuite's own gripper class does.

robosuite hard-codes each gripper's ``format_action`` in Python; our specs declare it (``actions:``).
For each of robosuite's 16 grippers, the class built from our spec and robosuite's own class get
the same 500 random actions (with the state reset every 100, as ``Robot.reset`` does) and must give
the same outputs, bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from robosuite.models.grippers import GRIPPER_MAPPING  # noqa: E402

import assembler.robosuite  # noqa: E402, F401
from assembler.models import REGISTERED_GRIPPERS  # noqa: E402
from assembler.robosuite.part_classes import robosuite_class_of  # noqa: E402

ROBOSUITES = {
    cls.__name__: cls for cls in GRIPPER_MAPPING.values() if cls.__module__.startswith("robosuite.")
}


@pytest.mark.parametrize("name", sorted(ROBOSUITES))
def test_declared_actions_give_robosuites_outputs(name: str) -> None:
    theirs = ROBOSUITES[name](idn="0_right")
    ours = robosuite_class_of(REGISTERED_GRIPPERS[name])(idn="0_right")
    assert (ours.dof, ours.speed, ours.actuators) == (theirs.dof, theirs.speed, theirs.actuators)
    rng = np.random.default_rng(0)
    for step in range(500):
        if step % 100 == 0:
            theirs.current_action = np.zeros(theirs.dof)
            ours.current_action = np.zeros(ours.dof)
        action = rng.choice([-1.0, 1.0, 0.0, 0.3, -0.7], size=theirs.dof) * rng.uniform(
            0.1, 2.0, size=theirs.dof
        )
        expected = np.asarray(theirs.format_action(action.copy()), dtype=float)
        got = np.asarray(ours.format_action(action.copy()), dtype=float)
        assert got.shape == expected.shape and np.array_equal(got, expected), (
            f"step {step}: {got} != {expected}"
        )


def test_a_gripper_with_actuators_and_no_actions_cannot_enter_robosuite(tmp_path) -> None:  # type: ignore[no-untyped-def]
    spec = tmp_path / "silent_gripper.yaml"
    spec.write_text("kind: gripper\nname: SilentGripper\nextends: PincerGripper\nactions: null\n")
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(assembler.SpecError, match="no 'actions:'") as error:
        robosuite_class_of(cls)(idn=0)
    assert "silent_gripper.yaml:4" in str(error.value)
