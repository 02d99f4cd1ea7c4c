"""``assembler list`` tells the project's shipped specs from a lab's own, though both read ``specs/...``."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from tests.conftest import GRIPPER_MJCF


def test_shipped_specs_are_marked_and_a_labs_are_not(
    capsys: pytest.CaptureFixture[str], write: Callable[[str, str], Path], monkeypatch: pytest.MonkeyPatch
) -> None:
    write("specs/pinch.xml", GRIPPER_MJCF)
    lab = write("specs/pinch.yaml", "kind: gripper\nname: LabPinch\nmjcf: pinch.xml\n")
    assembler.register_specs(lab)
    monkeypatch.chdir(lab.parents[1])
    assert main(["list", "grippers"]) == 0
    rows = {line.split()[0]: line.split()[2:] for line in capsys.readouterr().out.splitlines()[1:]}
    assert rows["LabPinch"] == ["specs/pinch.yaml"]
    assert rows["PandaGripper"] == ["specs/robosuite/grippers/panda_gripper.yaml", "(shipped)"]
