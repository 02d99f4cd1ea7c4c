"""``lint.acknowledge``: a finding a spec accepts with a reason is reported as acknowledged, not hidden,
and fails nothing; an acknowledgement that matches nothing is reported; shipped specs lint clean."""

from __future__ import annotations

import pytest

from assembler.cli import main
from tests.tools.test_lint import PROBE_SPEC, Write, codes, lint_json, probe

OUT_OF_RANGE = PROBE_SPEC.replace("-0.5", "-2.5")

ACKNOWLEDGED = """\
lint:
  acknowledge:
    - code: RA601
      reason: the vendor's own home pose, kept for parity
"""


def test_an_acknowledged_error_is_reported_with_its_reason_and_does_not_fail(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    spec = probe(write, spec=OUT_OF_RANGE + ACKNOWLEDGED)
    assert main(["lint", str(spec)]) == 0
    out = capsys.readouterr().out.splitlines()
    assert out[0].endswith(
        "acknowledged error RA601 robot0_elbow: the home keyframe sets -2.5 (init_qpos[1]), outside the "
        "joint's range [-2, 2]"
    )
    assert out[1:] == [
        "    acknowledged: the vendor's own home pose, kept for parity",
        "Probe: 1 acknowledged",
    ]

    code, findings = lint_json(capsys, str(spec))
    assert (code, codes(findings)) == (0, [("RA601", "error", "robot0_elbow")])
    assert findings[0]["acknowledged"] == "the vendor's own home pose, kept for parity"


def test_an_acknowledgement_that_matches_no_finding_is_reported_where_it_is_written(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    code, findings = lint_json(capsys, str(probe(write, spec=PROBE_SPEC + ACKNOWLEDGED)))
    assert (code, codes(findings)) == (0, [("RA002", "warning", "Probe")])
    assert findings[0]["why"] == "lint.acknowledge[0] accepts RA601, but lint finds no RA601 about this part"
    assert (findings[0]["line"], findings[0]["column"]) == (7, 7)


def test_an_acknowledgement_needs_a_code_and_a_reason(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    spec = probe(write, spec=OUT_OF_RANGE + "lint:\n  acknowledge:\n    - code: RA601\n")
    assert main(["lint", str(spec)]) == 1
    assert capsys.readouterr().err.endswith(
        "probe.yaml:7:7: lint.acknowledge[0]: missing required field 'reason'; add it\n"
    )


@pytest.mark.parametrize("name", ["Robotiq85Gripper", "Robotiq140Gripper", "UR5e", "SpotArm"])
def test_shipped_specs_with_robosuites_known_flaws_lint_without_failing(
    capsys: pytest.CaptureFixture[str], name: str
) -> None:
    pytest.importorskip("robosuite")  # their model files are read from the installed robosuite package
    code, findings = lint_json(capsys, name)
    assert code == 0
    assert {f["code"] for f in findings if f["acknowledged"]} & {"RA101", "RA601"}
    assert not [f for f in findings if f["severity"] == "error" and not f["acknowledged"]]
