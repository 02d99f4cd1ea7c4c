"""Lint agrees with the bridge: every refusal ``assembler.robosuite`` can raise about a spec has a lint
rule that fires, as an error, on a spec that provokes it; and the bridge refuses that same spec.

The refusals are read from the source (every ``raise`` in assembler/robosuite/*.py): each is either
in REFUSALS (a spec provokes it; its rule and a provoking case) or in NOT_ABOUT_A_SPEC (with why), so a
new refusal fails this test until it is given a rule or a reason.
"""

from __future__ import annotations

import ast
import json
from pathlib import Path
from typing import Any

import pytest

import assembler
from assembler.errors import AssemblerError
from tests.tools.test_lint import FINGER_MJCF, FINGER_SPEC, PROBE_MJCF, PROBE_SPEC, Write, lint_json

BRIDGE = Path(__file__).parents[2] / "assembler" / "robosuite"

NOT_ABOUT_A_SPEC: dict[tuple[str, str], str] = {
    ("__init__.py", "has no attribute"): "a Python attribute lookup on the package",
    (
        "__main__.py",
        "AssemblerError(str(error))",
    ): "python -m assembler.robosuite where robosuite cannot load",
    ("compat.py", "RobosuiteChanged("): "robosuite's own code changed: the patch is skipped with one line",
    ("autoload.py", "RegistryError("): "the autoload environment variable names folders that do not load",
    ("bridge.py", "ImportError("): "robosuite is not installed",
    ("bridge.py", "_why_not_replaced"): "replace_robosuite() called with names that are not robosuite's",
    (
        "controllers.py",
        "FileNotFoundError(name)",
    ): "internal: caught by declared_config, which says RA708's words",
    (
        "registrations.py",
        "robots with arms, grippers and bases only",
    ): "a Python class that is no manipulator",
    ("registrations.py", "ValueError("): "internal: a registration record of another format, read again",
    (
        "registrations.py",
        "_Unrecorded",
    ): "internal: a held name its file does not define, looked up as before",
    ("registries.py", "RegistryError(problems)"): "a name robosuite's own classes take, in this environment",
    ("robot_class.py", "is made per spec"): "SpecRobot used directly instead of robot_class(name)",
    ("robot_class.py", "has no end-effector body named"): "robosuite's add_gripper called with a wrong body",
    ("robot_class.py", "Mount already added"): "robosuite's add_base called twice (robosuite's own words)",
    ("robot_class.py", "multiple grippers to one body"): "robosuite's add_gripper called twice on one arm",
    ("part_classes.py", "is neither a gripper nor a base"): "internal: called with a robot class",
    ("robot_class.py", "has no spec"): "robosuite's own part given to a spec robot: an environment's choice",
    ("same_names.py", "name their elements differently"): "robosuite's own part beside a spec of its name",
    ("lossless.py", "written for"): "internal: the emitted XML lost an element (a bug, not a spec)",
    ("lossless.py", "MuJoCo wrote no <worldbody>"): "internal: MuJoCo's writer failed",
}
"""Refusals no spec provokes, by (file, a piece of the raise's source), and why."""

NO_ACTIONS = {"hand/finger.xml": FINGER_MJCF, "hand/finger.yaml": FINGER_SPEC.split("actions:")[0]}
NO_TORQUE = PROBE_SPEC.replace("robosuite: {actuation: torque}\n", "")
IN_VOLTS = NO_TORQUE + "motors:\n  - {match: '*', motor: MaxonECmax22, gear_ratio: 53, control: voltage}\n"
"""The probe's joints driven in volts by a shipped motor (its actuators replace the servos)."""


def _probe(spec: str = PROBE_SPEC, mjcf: str = PROBE_MJCF, **more: str) -> dict[str, str]:
    return {
        "probe/probe.xml": mjcf,
        **{f"probe/{name}": text for name, text in more.items()},
        "probe/probe.yaml": spec,
    }


def _controller(value: str, **more: str) -> dict[str, str]:
    return _probe(
        PROBE_SPEC.replace("{actuation: torque}", f"{{actuation: torque, controller: {value}}}"), **more
    )


REFUSALS: dict[tuple[str, str], tuple[str, dict[str, str], str]] = {
    ("parts.py", "JOINT_GROUPS"): (
        "RA705",
        _probe(
            mjcf=PROBE_MJCF.replace(
                '<position name="act_elbow" joint="elbow" kp="100" dampratio="1" ctrlrange="-2 2" forcerange="-40 40"/>',
                "",
            )
        ),
        "but elbow has none",
    ),
    ("parts.py", "are position servos"): ("RA701", _probe(NO_TORQUE), "are position servos"),
    ("parts.py", "take volts"): ("RA701", _probe(IN_VOLTS), "the actuators shoulder, elbow take volts"),
    ("parts.py", "no forcerange to become"): (
        "RA701",
        _probe(mjcf=PROBE_MJCF.replace(' forcerange="-40 40"', "")),
        "have no forcerange",
    ),
    ("part_classes.py", "spec_problem(ACTIONS"): ("RA703", NO_ACTIONS, "but no 'actions:'"),
    ("robot_class.py", "SpecError(problems)"): (
        "RA706",
        _probe(PROBE_SPEC + "base_xpos_offset: {bins: [table_length, 0, 0]}\n"),
        "base_xpos_offset.bins",
    ),
    ("lossless.py", "eulerseq"): (
        "RA707",
        _probe(mjcf=PROBE_MJCF.replace('autolimits="true"', 'autolimits="true" eulerseq="zyx"')),
        "eulerseq",
    ),
    ("controllers.py", "needs 'type' and 'body_parts'"): ("RA708", _controller("{parts: 1}"), "needs 'type'"),
    ("controllers.py", "cannot read"): ("RA708", _controller("missing.json"), "cannot read"),
    ("controllers.py", "CONTROLLER, str(error)"): (
        "RA708",
        _controller("../outside.json", **{"../outside.json": "{}"}),
        "outside the folders",
    ),
    ("controllers.py", "is not a controller configuration"): (
        "RA708",
        _controller("bad.json", **{"bad.json": "[1]"}),
        "is not a controller configuration",
    ),
    ("controllers.py", "robosuite has no controller configuration"): (
        "RA708",
        _controller("NOPE"),
        "robosuite has no controller configuration 'NOPE'",
    ),
}
"""Refusals a spec provokes, by (file, a piece of the raise's source): the lint rule, files (written in
order, the last one linted) that break only that, and words of the bridge's refusal of them."""


def _raises() -> list[tuple[str, str]]:
    """(file, source text) of every raise in the bridge's modules."""
    found = []
    for path in sorted(BRIDGE.glob("*.py")):
        text = path.read_text()
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Raise) and node.exc is not None:
                found.append((path.name, ast.get_source_segment(text, node) or ""))
    return found


def _entry(file: str, source: str, table: dict[tuple[str, str], Any]) -> list[tuple[str, str]]:
    return [key for key in table if key[0] == file and key[1] in source]


def test_every_refusal_of_the_bridge_has_a_lint_rule_or_a_reason_it_is_not_about_a_spec() -> None:
    unlisted = []
    for file, source in _raises():
        keys = _entry(file, source, REFUSALS) + _entry(file, source, NOT_ABOUT_A_SPEC)
        if len(keys) != 1:
            unlisted.append(f"{file}: {source.splitlines()[0]} -> {keys}")
    assert unlisted == []
    listed = {
        key for file, source in _raises() for key in _entry(file, source, {**REFUSALS, **NOT_ABOUT_A_SPEC})
    }
    assert listed == set(REFUSALS) | set(NOT_ABOUT_A_SPEC)  # no entry outlives its raise


def _bridge_refuses(part: type[Any]) -> None:
    """Raise what the bridge raises on the way to robosuite.make for this spec's part."""
    pytest.importorskip("robosuite")
    # Imported here: these modules import robosuite, which the enumeration test above does not need.
    from assembler.robosuite.controllers import declared_config
    from assembler.robosuite.lossless import lossless_xml
    from assembler.robosuite.part_classes import robosuite_class_of
    from assembler.robosuite.parts import drive_as_declared
    from assembler.robosuite.robot_class import robot_class

    if part.family == "gripper":
        robosuite_class_of(part)(idn=0)
        return
    robot = part(idn=0)
    lossless_xml(robot.part_mjspec())
    robot_class(part)
    declared_config(part)
    drive_as_declared(robot, robot.part_mjspec())


@pytest.mark.parametrize("refusal", sorted(REFUSALS), ids=lambda key: f"{key[0]}:{key[1]}")
def test_each_refusal_is_a_lint_error_on_the_spec_the_bridge_refuses(
    capsys: pytest.CaptureFixture[str], write: Write, refusal: tuple[str, str]
) -> None:
    code, files, refused = REFUSALS[refusal]
    if code == "RA708":  # robosuite's configurations are robosuite's files: without it lint says so (info)
        pytest.importorskip("robosuite")
    paths = [write(name, text) for name, text in files.items()]
    status, findings = lint_json(capsys, str(paths[-1]))
    fired = [f for f in findings if f["code"] == code]
    assert status == 1 and fired and all(f["severity"] == "error" for f in fired), json.dumps(
        findings, indent=1
    )
    (part,) = assembler.register_specs(paths[-1])
    with pytest.raises(AssemblerError, match=refused):
        _bridge_refuses(part)
