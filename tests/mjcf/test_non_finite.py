"""A NaN or an infinity in a vendor's MJCF: MuJoCo keeps it (a NaN position, warning only that the file
holds a NaN somewhere; an infinite size, in silence). The build says each at its line, as a URDF's are
said; ``assembler new`` refuses the file in one line per value, since no home pose, servo or
footprint can be read off them, and writes nothing."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from assembler.cli import main
from tests.conftest import TWO_LINK_MJCF

NAN_POSITION = TWO_LINK_MJCF.replace(
    '<body name="link2" pos="0.3 0 0">', '<body name="link2" pos="0.3 nan 0">'
)
INFINITE_SIZE = TWO_LINK_MJCF.replace(
    '<site name="right_center" size="0.01"/>', '<site name="right_center" size="inf"/>'
)
SAID = (
    "holds a value that is not a finite number: MuJoCo keeps it as written (a NaN position makes every "
    "step NaN, an infinite size a geom without bounds); correct the file"
)


def _line(text: str, written: str) -> int:
    return next(number for number, line in enumerate(text.splitlines(), start=1) if written in line)


@pytest.mark.filterwarnings("default::assembler.errors.AssemblerWarning")  # shown as the CLI shows it
@pytest.mark.parametrize(
    ("text", "written"),
    [(NAN_POSITION, '<body pos="0.3 nan 0">'), (INFINITE_SIZE, '<site size="inf">')],
    ids=["nan-position", "infinite-size"],
)
def test_the_build_says_each_value_at_its_line(
    text: str, written: str, write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/twolink.xml", text)
    spec = write("robots/twolink.yaml", "name: TwoLinkOdd\nmjcf: twolink.xml\n")
    code = main(["validate", "--compile", str(spec)])
    line = _line(text, "nan" if "nan" in written else 'size="inf"')
    err = capsys.readouterr().err.splitlines()
    assert f"warning: {model}:{line}: {written} {SAID}" in err
    # MuJoCo 3.11 and 4 keep a NaN position; MuJoCo 3.9 refuses the file itself, after the line saying where
    assert code == 0 or "MuJoCo refuses it" in err[-1]


@pytest.mark.filterwarnings("default::assembler.errors.AssemblerWarning")  # shown as the CLI shows it
def test_new_refuses_a_file_with_a_nan_in_one_line_and_writes_nothing(
    write: Callable[[str, str], Path], capsys: pytest.CaptureFixture[str]
) -> None:
    model = write("robots/twolink.xml", NAN_POSITION)
    spec = model.with_name("twolink.yaml")
    assert main(["new", str(model), "-o", str(spec)]) == 1
    err = capsys.readouterr().err
    line = _line(NAN_POSITION, "nan")
    said = f'{model}:{line}: <body pos="0.3 nan 0"> {SAID}'
    refusals = [row for row in err.splitlines() if not row.startswith("warning: ")]
    if len(refusals) == 1 and "MuJoCo refuses it" in refusals[0]:  # MuJoCo 3.9 refuses a NaN itself:
        assert f"warning: {said}" in err.splitlines()  # the line saying where comes before its refusal
    else:  # MuJoCo 3.11 and 4 keep it
        assert refusals == [f"{said}; new reads a robot only from finite numbers"]
    assert "Traceback" not in err and not spec.exists()
