"""Every name a spec gives is checked by ``assembler validate`` (no compile), at its position, with
the closest name that exists: registered bases and grippers, bodies, joints, sites, geoms and
sensors of the MJCF (joint overrides, declared actuators, contact exclusions), parents, and the robots, bases and grippers of scenes and experiments.

Each row is one file with one typo and the exact line ``validate`` prints for it.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from assembler.cli import main
from tests.conftest import GRIPPER_MJCF, MOBILE_MJCF, TWO_LINK_MJCF

Write = Callable[[str, str], Path]

ARM = "name: Arm\nmjcf: arm.xml\n"
CART = "kind: base\nname: Cart\ntype: mobile\nmjcf: cart.xml\n"
HAND = "kind: gripper\nname: Hand\nmjcf: hand.xml\n"
JOINTS = "Joints: shoulder, elbow"

# fmt: off
CASES = [
    pytest.param(ARM + "default_base: Pedestl\n", "3:15: default_base: unknown base 'Pedestl'. Did you mean 'Pedestal'?", id="robot-default-base"),
    pytest.param(ARM + "default_grippers: {right: TriHnd}\n", "3:27: default_grippers.right: unknown gripper 'TriHnd'. Did you mean 'TriHand'?", id="robot-default-gripper"),
    pytest.param(ARM + "eef_bodies: {right: right_hnd}\n", "3:21: eef_bodies.right: no body named 'right_hnd' in the MJCF. Did you mean 'right_hand'? Bodies: base, link1, link2, right_hand", id="robot-eef-body"),
    pytest.param(ARM + "joint_groups: {torso: [elbw]}\n", f"3:24: joint_groups.torso[0]: no joint matches 'elbw'. Did you mean 'elbow'? {JOINTS}", id="robot-joint-group"),
    pytest.param(ARM + "remove_actuation: [shouldr]\n", f"3:20: remove_actuation[0]: no joint matches 'shouldr'. Did you mean 'shoulder'? {JOINTS}", id="robot-remove-actuation"),
    pytest.param(ARM + "joints:\n  - {match: 'elb?x', damping: 1}\n", f"4:13: joints[0].match: no joint matches 'elb?x'. Did you mean 'elbow'? {JOINTS}", id="robot-joint-override"),
    pytest.param(ARM + "actuators:\n  - {match: 'elbw', kp: 10}\n", f"4:13: actuators[0].match: no joint matches 'elbw'. Did you mean 'elbow'? {JOINTS}", id="robot-actuator"),
    pytest.param(ARM + "contact_excludes: [[base, lnk2]]\n", "3:27: contact_excludes[0][1]: no body named 'lnk2' in the MJCF. Did you mean 'link2'? Bodies: base, link1, link2, right_hand", id="robot-contact-exclude"),
    pytest.param(ARM + "extends: Sparow7\n", "3:10: extends: unknown robot spec 'Sparow7'. Did you mean 'Sparrow7'?", id="robot-extends"),
    pytest.param(CART + "support_body: supprt\n", "5:15: support_body: no body named 'supprt' in the MJCF. Did you mean 'support'? Bodies: base, lift, support", id="base-support-body"),
    pytest.param(CART + "joint_groups: {base: [joint_mobile_fwd]}\n", "5:23: joint_groups.base[0]: no joint matches 'joint_mobile_fwd'. Did you mean 'joint_mobile_forward'? Joints: joint_mobile_forward, joint_mobile_yaw, joint_torso_height", id="base-joint-group"),
    pytest.param(CART + "extends: RoverBse\n", "5:10: extends: unknown base spec 'RoverBse'. Did you mean 'RoverBase'?", id="base-extends"),
    pytest.param(HAND + "eef_body: eff\n", "4:11: eef_body: no body named 'eff' in the MJCF. Did you mean 'eef'? Bodies: eef, finger, pinch_root", id="gripper-eef-body"),
    pytest.param(HAND + "important_sites: {grip_site: grip_sit}\n", "4:30: important_sites.grip_site: no site named 'grip_sit' in the MJCF. Did you mean 'grip_site'? Sites: ft_frame, grip_site, grip_site_cylinder", id="gripper-site"),
    pytest.param(HAND + "important_geoms: {left_fingerpad: [finger_pad]}\n", "4:36: important_geoms.left_fingerpad[0]: no geom named 'finger_pad' in the MJCF. Did you mean 'finger_pad_col'? Geoms: finger_pad_col, palm_col", id="gripper-geom"),
    pytest.param(HAND + "important_sensors: {force_ee: force_e}\n", "4:31: important_sensors.force_ee: no sensor named 'force_e' in the MJCF. Did you mean 'force_ee'? Sensors: force_ee, torque_ee", id="gripper-sensor"),
]
# fmt: on


def _lab(write: Write) -> None:
    write("lab/arm.xml", TWO_LINK_MJCF)
    write("lab/cart.xml", MOBILE_MJCF)
    write("lab/hand.xml", GRIPPER_MJCF)


@pytest.mark.parametrize(("text", "expected"), CASES)
def test_validate_names_each_typo_at_its_position(
    text: str, expected: str, write: Write, capsys: pytest.CaptureFixture[str]
) -> None:
    _lab(write)
    spec = write("lab/typo.yaml", text)
    assert main(["validate", str(spec)]) == 1
    assert capsys.readouterr().err.splitlines() == [f"{spec}:{expected}"]


def test_every_typo_of_a_spec_is_reported_at_once(write: Write, capsys: pytest.CaptureFixture[str]) -> None:
    _lab(write)
    spec = write(
        "lab/typos.yaml",
        ARM + "default_base: Pedestl\ndefault_grippers: {right: TriHnd}\n"
        "eef_bodies: {right: right_hnd}\njoint_groups: {torso: [elbw]}\n",
    )
    assert main(["validate", str(spec)]) == 1
    fields = [line.split(": ")[1] for line in capsys.readouterr().err.splitlines()]
    assert fields == ["default_base", "default_grippers.right", "eef_bodies.right", "joint_groups.torso[0]"]


@pytest.mark.parametrize("kind", ["scene", "experiment"])
def test_robots_bases_and_grippers_of_scenes_and_experiments_are_checked(
    kind: str, write: Write, capsys: pytest.CaptureFixture[str]
) -> None:
    path = write(
        f"lab/{kind}.yaml",
        f"kind: {kind}\nname: pair\nrobots:\n  - robot: Sparow7\n"
        "  - robot: Finch6\n    base: Pedestl\n    grippers: {right: TriHnd}\n",
    )
    assert main(["validate", str(path)]) == 1
    assert capsys.readouterr().err.splitlines() == [
        f"{path}:4:12: robots[0].robot: unknown robot 'Sparow7'. Did you mean 'Sparrow7'?",
        f"{path}:6:11: robots[1].base: unknown base 'Pedestl'. Did you mean 'Pedestal'?",
        f"{path}:7:23: robots[1].grippers.right: unknown gripper 'TriHnd'. Did you mean 'TriHand'?",
    ]


def test_a_name_with_no_close_match_lists_the_names_of_its_kind(
    write: Write, capsys: pytest.CaptureFixture[str]
) -> None:
    _lab(write)
    spec = write("lab/far.yaml", ARM + "default_base: Zzzzzz\n")
    assert main(["validate", str(spec)]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    assert line.startswith(f"{spec}:3:15: default_base: unknown base 'Zzzzzz'. Registered bases: ")
    assert "Pedestal" in line and "Sparrow7" not in line
