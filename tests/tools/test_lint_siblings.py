"""A spec file given by path sees the part specs beside it (``lint specs/z1_with_gripper.yaml`` with
``z1_gripper.yaml`` there), a broken one beside it never blocks it, and an unknown name says --specs."""

from __future__ import annotations

import pytest

from assembler.cli import main
from tests.conftest import GRIPPER_MJCF
from tests.tools.test_lint import PROBE_SPEC, Write, lint_json, probe

WITH_GRIPPER = PROBE_SPEC + "default_grippers: {right: Pinch}\n"


def test_a_spec_path_finds_the_gripper_spec_beside_it(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    write("probe/pinch.xml", GRIPPER_MJCF)
    write(
        "probe/pinch.yaml",
        "kind: gripper\nname: Pinch\nmjcf: pinch.xml\nactions: {dimensions: [{actuators: [finger_act]}]}\n",
    )
    write("probe/scene.yaml", "kind: scene\nname: S\nrobots: [{robot: Probe}]\n")  # not a part: left alone
    code, findings = lint_json(capsys, str(probe(write, spec=WITH_GRIPPER)))
    report = capsys.readouterr()
    assert code == 0, report
    assert findings and all(
        f["subject"] == "Pinch" or f["subject"].startswith("gripper0_right_") for f in findings
    )


def test_a_broken_spec_beside_it_does_not_block_it(capsys: pytest.CaptureFixture[str], write: Write) -> None:
    write("probe/broken.yaml", "name: Broken\nmjcf: nowhere.xml\ninit_qpos: [x]\n")
    assert main(["lint", str(probe(write))]) == 0
    assert capsys.readouterr().out == "Probe: no findings\n"


def test_an_unknown_gripper_says_how_to_add_a_spec_folder(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    assert main(["lint", str(probe(write, spec=WITH_GRIPPER.replace("Pinch", "Zzzzqq")))]) == 1
    assert (
        capsys.readouterr()
        .err.rstrip()
        .endswith(
            "a spec in another folder is found with --specs FOLDER (assembler.register_specs in Python)"
        )
    )
