"""RA102 and root_pose: a gripper whose file places it far from the hand is reported, and can be reset."""

from __future__ import annotations

import numpy as np
import pytest

import assembler
from tests.tools.test_lint import PROBE_SPEC, Write, codes, lint_json, probe

FLOATING_HAND = """\
<mujoco model="floating">
  <worldbody>
    <body name="hand_root" pos="1.0 1.25 0.15" euler="0 0 90">
      <geom name="palm_col" type="box" size="0.02 0.04 0.02" mass="0.3"/>
      <geom name="palm_vis" type="box" size="0.02 0.04 0.02" group="1" contype="0" conaffinity="0"/>
    </body>
  </worldbody>
</mujoco>
"""
"""As gymnasium-robotics' Shadow hand: its root placed in the scene it was written for."""

HAND_SPEC = "kind: gripper\nname: Floating\nmjcf: floating.xml\neef_body: hand_root\n"


def _robot_with_hand(write: Write, hand_spec: str) -> str:
    write("probe/floating.xml", FLOATING_HAND)
    write("probe/floating.yaml", hand_spec)
    return str(probe(write, spec=PROBE_SPEC + "default_grippers: {right: Floating}\n"))


def test_a_gripper_far_from_the_hand_is_reported(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    code, findings = lint_json(capsys, _robot_with_hand(write, HAND_SPEC))
    assert code == 0
    assert codes(findings) == [
        ("RA102", "warning", "gripper0_right_hand_root"),
        ("RA702", "info", "Floating"),
    ]
    far = findings[0]
    assert far["why"] == (
        "the gripper's root body lies 1.61 m from robot0_right_hand, where it is mounted: its file places it "
        "elsewhere (in a scene?), and the gripper floats away from the arm"
    )


def test_root_pose_reset_puts_the_gripper_on_the_hand(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    spec = _robot_with_hand(write, HAND_SPEC + "root_pose: reset\n")
    code, findings = lint_json(capsys, spec)
    assert (code, codes(findings)) == (0, [("RA702", "info", "Floating")])
    assembler.register_specs(write("probe/floating.yaml", HAND_SPEC + "root_pose: reset\n").parent)
    model = assembler.assemble("Probe").get_model(cache=False)
    assert np.allclose(model.body("gripper0_right_hand_root").pos, 0)
    assert np.allclose(model.body("gripper0_right_hand_root").quat, [1, 0, 0, 0])
