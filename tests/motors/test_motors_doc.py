"""docs/motors.md's worked example is what the code does: its spec validates, and `assembler inspect`
prints exactly the derivation lines the page shows."""

from __future__ import annotations

from pathlib import Path

import pytest

from assembler.cli import main
from tests.motors.rigs import SPINNER_MJCF, Write

PAGE = Path(__file__).parents[2] / "docs" / "motors.md"


def _blocks(language: str) -> list[str]:
    """The page's fenced code blocks of ``language`` ("" for plain ones), in order."""
    blocks: list[str] = []
    current: list[str] | None = None
    opening = ""
    for line in PAGE.read_text().splitlines():
        if line.startswith("```") and current is None:
            current, opening = [], line[3:]
        elif line.startswith("```") and current is not None:
            if opening == language:
                blocks.append("\n".join(current) + "\n")
            current = None
        elif current is not None:
            current.append(line)
    return blocks


def test_the_worked_example_prints_the_derivation_the_page_shows(
    write: Write, capsys: pytest.CaptureFixture[str]
) -> None:
    (spec,) = [block for block in _blocks("yaml") if "name: Wrist" in block]
    write("doc/wrist.xml", SPINNER_MJCF.format(extra="").replace('name="spin"', 'name="wrist"'))
    folder = write("doc/wrist.yaml", spec).parent
    assert main(["--specs", str(folder), "inspect", "Wrist"]) == 0
    printed = capsys.readouterr().out
    shown = [block for block in _blocks("") if block.startswith("from the motors")]
    assert shown and shown[0].strip() in printed
