"""``assembler lint`` on tiny robots that each break one rule, GitHub annotations, and the pre-commit hooks."""

from __future__ import annotations

import argparse
import json
import re
from collections.abc import Callable
from importlib.metadata import entry_points
from pathlib import Path

import pytest
import yaml

import assembler.registry.catalog  # noqa: F401  (registers the shipped specs)
from assembler.cli import build_parser, main
from assembler.cli.checking import github_annotation
from assembler.errors import Location

ROOT = Path(__file__).parents[2]
Write = Callable[[str, str], Path]

PROBE_MJCF = """\
<mujoco model="probe">
  <compiler angle="radian" autolimits="true"/>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="cylinder" size="0.05 0.05" mass="2"/><geom name="base_vis" type="cylinder" size="0.05 0.05" group="1" contype="0" conaffinity="0" mass="0"/><site name="right_center"/>
      <body name="link1" pos="0 0 0.1">
        <joint name="shoulder" axis="0 0 1" range="-2 2"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <body name="link2" pos="0.3 0 0">
          <joint name="elbow" axis="0 1 0" range="-2 2"/>
          <geom name="link2_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.025" mass="0.5"/>
          <body name="right_hand" pos="0.3 0 0"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="act_shoulder" joint="shoulder" kp="200" dampratio="1" ctrlrange="-2 2" forcerange="-80 80"/>
    <position name="act_elbow" joint="elbow" kp="100" dampratio="1" ctrlrange="-2 2" forcerange="-40 40"/>
  </actuator>
</mujoco>
"""
"""A clean two-link arm (no findings: it has a visual geom, so robosuite's cameras see it, and the
right_center site and force ranges robosuite's controllers need); each test breaks one thing in it."""

PROBE_SPEC = "name: Probe\nmjcf: probe.xml\ninit_qpos: [0.3, -0.5]\nrobosuite: {actuation: torque}\n"

FINGER_MJCF = """\
<mujoco model="finger">
  <compiler autolimits="true"/>
  <worldbody>
    <body name="palm">
      <geom name="palm_col" type="box" size="0.02 0.04 0.02" pos="0 0 0.02" mass="0.3"/>
      <body name="finger" pos="0 0 0.05">
        <joint name="finger_joint" type="slide" axis="0 1 0" range="0 0.03"/>
        <geom name="pad_col" type="box" size="0.01 0.01 0.02" mass="0.05"/>
        <geom name="pad_vis" type="box" size="0.01 0.01 0.02" contype="0" conaffinity="0" group="1"/>
      </body>
      <body name="eef" pos="0 0 0.1">
        <site name="grip_site" size="0.005"/>
        <site name="grip_site_cylinder" size="0.005"/>
        <site name="ft_frame" size="0.005"/>
      </body>
    </body>
  </worldbody>
  <actuator><position name="finger_act" joint="finger_joint" kp="100" ctrlrange="0 0.03"/></actuator>
  <sensor><force name="force_ee" site="ft_frame"/><torque name="torque_ee" site="ft_frame"/></sensor>
</mujoco>
"""


def lint_json(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, list[dict[str, object]]]:
    code = main(["lint", *argv, "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    return code, [finding for target in report["targets"] for finding in target["findings"]]


def probe(write: Write, mjcf: str = PROBE_MJCF, spec: str = PROBE_SPEC) -> Path:
    write("probe/probe.xml", mjcf)
    return write("probe/probe.yaml", spec)


def codes(findings: list[dict[str, object]]) -> list[tuple[object, object, object]]:
    return [(f["code"], f["severity"], f["subject"]) for f in findings]


def test_a_clean_robot_has_no_findings(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    code = main(["lint", str(probe(write))])
    assert code == 0
    assert capsys.readouterr().out == "Probe: no findings\n"


def test_a_robot_with_only_collision_geoms_is_reported_invisible_to_robosuites_cameras(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    bare = re.sub(r'<geom name="base_vis"[^>]*/>', "", PROBE_MJCF)
    spec = probe(write, mjcf=bare)
    assert main(["lint", str(spec)]) == 0  # a warning
    assert capsys.readouterr().out.splitlines() == [
        f"{spec}:2:7: warning RA504 robot0_base: Probe has 3 geom(s), all in group(s) 0 and none in the "
        "visual groups 1, 2: robosuite's cameras and viewer hide group 0, so it is invisible there "
        "(assembler render draws its collision geoms instead)",
        '    fix: add visual geoms in group 1 with contype="0" conaffinity="0" (copies of the collision '
        'geoms will do), or put geoms meant to be seen in group="1"',
        "Probe: 1 warning",
    ]


def test_overlapping_parts_at_home_are_an_error_with_the_mjcf_line(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    # link2 (a grandchild of base, so MuJoCo does not filter the pair) reaches back into the base
    hook = '<geom name="hook_col" type="sphere" pos="-0.3 0 -0.1" size="0.04" mass="0.1"/>\n          <body name="right_hand"'
    spec = probe(
        write, PROBE_MJCF.replace('<body name="right_hand"', hook), PROBE_SPEC.replace("0.3, -0.5", "0, 0")
    )
    code = main(["lint", str(spec)])
    out = capsys.readouterr().out
    assert code == 1
    assert re.search(
        r"probe.xml:12:11: error RA101 robot0_base_col / robot0_hook_col: geoms of bodies robot0_base and "
        r"robot0_link2 overlap by \d+\.\d mm at the home pose",
        out,
    )
    assert "    fix: move the part (gripper_mount, the body's pos) or change init_qpos" in out
    assert out.endswith("Probe: 1 error\n")


def test_mass_and_inertia_implausible_for_the_geometry(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    heavy = PROBE_MJCF.replace('size="0.03" mass="1"', 'size="0.03" mass="50"')
    huge = heavy.replace(
        '<joint name="elbow"',
        '<inertial pos="0.15 0 0" mass="0.5" diaginertia="2 2 2"/>\n          <joint name="elbow"',
    )
    code, findings = lint_json(capsys, str(probe(write, huge)))
    assert code == 0  # warnings only
    assert codes(findings) == [("RA201", "warning", "robot0_link1"), ("RA203", "warning", "robot0_link2")]
    assert re.match(
        r"mass 50 kg in 9\d\d\.\d+ cm\^3 of geoms is a density of 5\.\d+e\+04 kg/m\^3",
        str(findings[0]["why"]),
    )
    assert findings[1]["why"] == (
        "inertia 2 kg m^2 for 0.5 kg is a radius of gyration of 2 m, but the geoms reach only 0.175 m "
        "from its centre of mass"
    )
    assert (findings[1]["line"], findings[1]["column"]) == (9, 9)  # <body name="link2">


def test_degenerate_inertias_are_errors(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    thin = PROBE_MJCF.replace(
        '<joint name="shoulder"',
        '<inertial pos="0 0 0" mass="1" diaginertia="1e-12 0.01 0.01"/>\n        <joint name="shoulder"',
    )
    unbalanced = thin.replace('autolimits="true"', 'autolimits="true" balanceinertia="true"').replace(
        '<joint name="elbow"',
        '<inertial pos="0 0 0" mass="0.5" diaginertia="0.01 0.001 0.001"/>\n          <joint name="elbow"',
    )
    code, findings = lint_json(capsys, str(probe(write, unbalanced)))
    assert code == 1
    assert codes(findings) == [("RA202", "error", "robot0_link1"), ("RA202", "error", "robot0_link2")]
    assert "a radius of gyration under 0.1 mm, as if it had no extent along one axis" in str(
        findings[0]["why"]
    )
    assert "violate A + B >= C (no physical body has them); MuJoCo's balanceinertia replaced them" in str(
        findings[1]["why"]
    )


def test_position_servo_ranges_and_unlimited_joints(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    wide = PROBE_MJCF.replace(
        'kp="200" dampratio="1" ctrlrange="-2 2"', 'kp="200" dampratio="1" ctrlrange="-3 2"'
    )
    unlimited = wide.replace('axis="0 1 0" range="-2 2"', 'axis="0 1 0"').replace(
        'kp="100" dampratio="1" ctrlrange="-2 2"', 'kp="100" dampratio="1"'
    )
    code, findings = lint_json(capsys, str(probe(write, unlimited)))
    assert code == 0
    assert codes(findings) == [
        ("RA301", "warning", "robot0_act_shoulder"),
        ("RA302", "warning", "robot0_elbow"),
    ]
    assert findings[0]["why"] == (
        "ctrlrange targets [-3, 2] reach 1 outside joint robot0_shoulder's range [-2, 2]: "
        "the servo can push the joint into its limit"
    )
    assert (findings[0]["line"], findings[1]["line"]) == (18, 10)  # the <position> and the <joint>


def test_armature_the_index_rule_made_tiny(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    spec = PROBE_SPEC + "joint_defaults:\n  armature: {inverse_index: 0.3}\n"
    code, findings = lint_json(capsys, str(probe(write, spec=spec)))
    assert code == 0
    assert codes(findings) == [("RA401", "warning", "robot0_elbow")]  # 0.3 / 2; the shoulder keeps 0.3
    assert findings[0]["why"] == (
        "armature 0.15 comes from the index rule (rule 0.3/(i+1)), not from the joint's motor: "
        "the rule shrinks it along the chain below 0.2"
    )
    assert str(findings[0]["file"]).endswith("probe/probe.yaml") and (
        findings[0]["line"],
        findings[0]["column"],
    ) == (6, 13)


def test_a_missing_end_effector_body_is_a_spec_problem_before_anything_is_linted(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    main_code = main(
        ["lint", str(probe(write, spec=PROBE_SPEC + "eef_bodies: {right: hand}\n")), "--format", "json"]
    )
    report = json.loads(capsys.readouterr().out)
    assert main_code == 1 and report["targets"] == []
    (problem,) = report["problems"]
    assert str(problem["file"]).endswith("probe/probe.yaml") and (problem["line"], problem["column"]) == (
        5,
        21,
    )
    assert problem["message"].endswith(
        "eef_bodies.right: no body named 'hand' in the MJCF. Bodies: base, link1, link2, right_hand"
    )


def test_gripper_without_fingerpads_or_with_a_pad_that_cannot_touch(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    # The pad overlaps the palm, its parent: MuJoCo filters that pair once the gripper is on a hand.
    write("hand/finger.xml", FINGER_MJCF)
    spec = write(
        "hand/finger.yaml",
        "kind: gripper\nname: Finger\nmjcf: finger.xml\nimportant_geoms:\n  left_fingerpad: [pad_vis]\n"
        "actions: {dimensions: [{actuators: [finger_act]}]}\n",
    )
    code, findings = lint_json(capsys, str(spec))
    assert code == 0
    assert codes(findings) == [("RA502", "warning", "Finger"), ("RA503", "warning", "gripper0_pad_vis")]
    assert (
        findings[0]["why"]
        == "important_geoms has no right_fingerpad: robosuite's grasp check has no pads to test"
    )


def test_home_pose_outside_a_joint_range_is_an_error(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    code, findings = lint_json(capsys, str(probe(write, spec=PROBE_SPEC.replace("-0.5", "-2.5"))))
    assert code == 1
    assert codes(findings) == [("RA601", "error", "robot0_elbow")]
    assert (
        findings[0]["why"] == "the home keyframe sets -2.5 (init_qpos[1]), outside the joint's range [-2, 2]"
    )
    assert (
        findings[0]["fix"]
        == "bring init_qpos[1] within [-2, 2] (radians for hinges), or fix the joint's range"
    )
    assert (findings[0]["line"], findings[0]["column"]) == (3, 18)


FINGER_SPEC = (
    "kind: gripper\nname: Finger\nmjcf: finger.xml\n"
    "important_geoms: {left_fingerpad: [pad_col], right_fingerpad: [pad_col]}\n"
    "actions: {dimensions: [{actuators: [finger_act]}]}\n"
)
"""The finger gripper with its pads and actions: no findings."""

UNSET = "set robosuite.actuation to torque (each servo becomes a motor whose ctrlrange is its forcerange) or to as_is (keep the servos)"

ROBOSUITE_CASES = {
    "servos without robosuite.actuation": (
        {
            "probe/probe.xml": PROBE_MJCF,
            "probe/probe.yaml": PROBE_SPEC.replace("robosuite: {actuation: torque}\n", ""),
        },
        ("RA701", "error", "Probe"),
        "the actuators robosuite's controllers drive (robot0_act_shoulder, robot0_act_elbow) are position "
        "servos, but those controllers write torques into ctrl and robosuite.actuation is not set: robosuite "
        "refuses the robot",
        UNSET,
    ),
    "actuation torque for a servo without forcerange": (
        {"probe/probe.xml": PROBE_MJCF.replace(' forcerange="-40 40"', ""), "probe/probe.yaml": PROBE_SPEC},
        ("RA701", "error", "robot0_act_elbow"),
        "robosuite.actuation is torque, but this position servo has no forcerange to become its motor's "
        "ctrlrange: robosuite refuses the robot",
        "give the actuator a forcerange (its torque or force limits), or set robosuite.actuation to as_is",
    ),
    "gripper without robosuite's eef body": (
        {
            "hand/finger.xml": FINGER_MJCF.replace('<body name="eef"', '<body name="tip"'),
            "hand/finger.yaml": FINGER_SPEC + "eef_body: tip\n",
        },
        ("RA702", "info", "Finger"),
        "robosuite looks a gripper up by body 'eef', sites 'grip_site' and 'grip_site_cylinder' and its force "
        "and torque sensors; this one lacks body 'eef', which robosuite gets at body 'tip' (eef_body; the "
        "sensors at the gripper's root)",
        "nothing, if body 'tip' is the grip point; else add them to the MJCF where the fingers close",
    ),
    "gripper with actuators and no actions": (
        {"hand/finger.xml": FINGER_MJCF, "hand/finger.yaml": FINGER_SPEC.split("actions:")[0]},
        ("RA703", "error", "Finger"),
        "the gripper has actuators (finger_act) but no actions: block saying how a policy's actions drive "
        "them: robosuite refuses it",
        "add actions: with one entry per action dimension, naming the actuators it drives and their "
        "direction (docs/robosuite.md, Gripper actions)",
    ),
    "arm without its center site": (
        {
            "probe/probe.xml": PROBE_MJCF.replace('<site name="right_center"/>', ""),
            "probe/probe.yaml": PROBE_SPEC,
        },
        ("RA704", "info", "robot0_right_center"),
        "robosuite's composite controller reads the right arm's origin from site right_center at every "
        "step, and the model has none: in robosuite's environments it is added on the body the arm's first "
        "link hangs from",
        'add <site name="right_center"/> to the body the right arm starts from (robosuite\'s Panda: link0), '
        "in the robot's MJCF",
    ),
}
"""Per RA7xx rule, files that break only it: the finding, why and fix."""


@pytest.mark.parametrize("case", sorted(ROBOSUITE_CASES))
def test_what_robosuite_would_refuse_is_reported_with_what_to_do(
    capsys: pytest.CaptureFixture[str], write: Write, case: str
) -> None:
    files, finding, why, fix = ROBOSUITE_CASES[case]
    paths = [write(name, text) for name, text in files.items()]
    code, findings = lint_json(capsys, str(paths[-1]))
    assert codes(findings) == [finding]
    assert (findings[0]["why"], findings[0]["fix"]) == (why, fix)
    assert code == (1 if finding[1] == "error" else 0)


def test_the_finger_gripper_with_pads_and_actions_is_clean(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    write("hand/finger.xml", FINGER_MJCF)
    assert main(["lint", str(write("hand/finger.yaml", FINGER_SPEC))]) == 0
    assert capsys.readouterr().out == "Finger: no findings\n"


def test_github_format_prints_annotations(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    code = main(["lint", str(probe(write, spec=PROBE_SPEC.replace("-0.5", "-2.5"))), "--format", "github"])
    (line,) = capsys.readouterr().out.splitlines()
    assert code == 1
    assert (
        line.startswith("::error file=")
        and ",line=3,col=18,title=RA601 (Probe)::robot0_elbow: the home" in line
    )


def test_annotations_escape_what_github_would_misread() -> None:
    location = Location("specs/a,b.yaml", 3, 5)
    assert github_annotation("info", "50% done\nnext", location, "RA1: x") == (
        "::notice file=specs/a%2Cb.yaml,line=3,col=5,title=RA1%3A x::50%25 done%0Anext"
    )
    assert github_annotation("error", "no place") == "::error::no place"


def test_validate_github_format_annotates_each_problem(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    spec = write("bad.yaml", "name: A\nmjcf: a.xml\njoint_defaults:\n  dampng: 1\n")
    code = main(["validate", str(spec), "--format", "github"])
    (line,) = capsys.readouterr().out.splitlines()
    assert code == 1
    assert re.fullmatch(
        r"::error file=\S*bad.yaml,line=4,col=3::joint_defaults.dampng: unknown key 'dampng'\. Did you mean 'damping'\?.*",
        line,
    )


def test_lint_reports_specs_that_do_not_load_like_validate(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    code = main(
        ["lint", str(write("bad.yaml", "name: A\nmjcf: a.xml\ninit_qpos: [0, x]\n")), "--format", "github"]
    )
    assert code == 1
    assert ",line=3,col=16::init_qpos[1]: Input should be a valid number" in capsys.readouterr().out


# Our own robots: every finding is real (see the README's "In review"); none is an error.
KNOWN_FINDINGS = {
    "Sparrow7": [("RA203", "warning", "robot0_link1")],  # Gaz et al.'s identified link-1 Ixx, Iyy
    "Finch6": [],
    "TwinTorso": [],
    "Biped": [("RA401", "warning", "robot0_r_ankle_roll")],  # 5/26 from robosuite's rule
}


@pytest.mark.parametrize("robot", sorted(KNOWN_FINDINGS))
def test_shipped_robots_have_only_their_known_findings(
    capsys: pytest.CaptureFixture[str], robot: str
) -> None:
    code, findings = lint_json(capsys, robot)
    assert code == 0 and codes(findings) == KNOWN_FINDINGS[robot]


def test_pre_commit_hooks_run_real_commands_on_spec_files(capsys: pytest.CaptureFixture[str]) -> None:
    hooks = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    scripts = {
        script.name for script in entry_points(group="console_scripts") if script.value == "assembler.cli:run"
    }
    (subcommands,) = [a for a in build_parser()._actions if isinstance(a, argparse._SubParsersAction)]
    commands = set(subcommands.choices)
    assert [hook["id"] for hook in hooks] == ["assembler-validate", "assembler-lint", "assembler-locked"]
    *per_file, locked = hooks
    program, command, *flags = locked["entry"].split()  # the whole repository's lock, no file names
    assert program in scripts and command in commands and not locked["pass_filenames"]
    assert build_parser().parse_args([command, *flags]).locked
    for hook in per_file:
        program, command, *flags = hook["entry"].split()
        assert program in scripts and command in commands and hook["language"] == "python"
        assert re.search(hook["files"], "specs/sparrow7.yaml") and re.search(
            hook["files"], "robots/specs/arm.yml"
        )
        assert not re.search(hook["files"], ".github/workflows/ci.yml")
        files = [str(ROOT / "specs" / "finch6.yaml"), str(ROOT / "specs" / "grippers" / "tri_hand.yaml")]
        build_parser().parse_args([command, *flags, *files])
        assert main([command, *flags, *files]) == 0, capsys.readouterr()


def test_a_range_a_few_microradians_too_wide_prints_the_digits_that_show_it(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    rounded = PROBE_MJCF.replace(
        'ctrlrange="-2 2" forcerange="-80 80"', 'ctrlrange="-2.0000027 2" forcerange="-80 80"'
    )
    code, findings = lint_json(capsys, str(probe(write, rounded)))
    assert codes(findings) == [("RA301", "warning", "robot0_act_shoulder")]
    assert findings[0]["why"] == (
        "ctrlrange targets [-2.000003, 2] reach 2.7e-06 outside joint robot0_shoulder's range [-2, 2]: "
        "the servo can push the joint into its limit"
    )
