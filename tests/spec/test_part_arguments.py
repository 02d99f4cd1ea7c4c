"""One answer to "what does this argument name?": every entry point takes a spec file, a spec folder
and a registered name alike, including names no file system can hold."""

from __future__ import annotations

import importlib
from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.errors import AssemblerError
from assembler.spec.part_arguments import ArgumentKind, argument_kind
from tests.conftest import TWO_LINK_MJCF, TWO_LINK_SPEC

TOO_LONG = "x" * 300  # longer than any file name the file system allows (ENAMETOOLONG)


def test_a_name_too_long_for_the_file_system_is_an_unknown_robot_to_load_model() -> None:
    with pytest.raises(AssemblerError, match="unknown robot 'x+'"):
        assembler.load_model(TOO_LONG, cache=False)


def test_a_name_too_long_for_the_file_system_is_an_unknown_robot_to_create_robot() -> None:
    with pytest.raises(AssemblerError, match="unknown robot 'x+'"):
        assembler.create_robot(TOO_LONG)


def test_a_name_too_long_for_the_file_system_is_one_line_from_build(
    capsys: pytest.CaptureFixture[str],
) -> None:
    assert main(["build", TOO_LONG, "--no-cache"]) == 1
    err = capsys.readouterr().err
    assert "unknown robot" in err and "Traceback" not in err


@pytest.mark.parametrize(
    ("reference", "kind"),
    [
        ("Sparrow7", ArgumentKind.NAME),
        ("missing.yaml", ArgumentKind.SPEC_FILE),  # a spec file by its suffix, even before it exists
        (TOO_LONG, ArgumentKind.NAME),
        ("two_link", ArgumentKind.SPEC_FILE),  # an existing file without a suffix
        ("folder", ArgumentKind.SPEC_FOLDER),
    ],
)
def test_every_argument_is_classified_one_way(
    reference: str, kind: ArgumentKind, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    (tmp_path / "two_link").write_text(TWO_LINK_SPEC)
    (tmp_path / "folder").mkdir()
    monkeypatch.chdir(tmp_path)
    assert argument_kind(reference) is kind


def test_a_scene_names_robot_files_relative_to_its_own_folder(tmp_path: Path) -> None:
    (tmp_path / "two_link").write_text(TWO_LINK_SPEC)
    assert argument_kind("two_link", tmp_path) is ArgumentKind.SPEC_FILE
    assert argument_kind("two_link", tmp_path / "elsewhere") is ArgumentKind.NAME


def test_a_spec_class_reports_a_module_that_exists(tmp_path: Path) -> None:
    (tmp_path / "twolink.xml").write_text(TWO_LINK_MJCF)
    (tmp_path / "two_link.yaml").write_text(TWO_LINK_SPEC)
    (cls,) = assembler.register_specs(tmp_path / "two_link.yaml")
    assert importlib.import_module(cls.__module__) is not None
    assert importlib.import_module(assembler.create_robot("Sparrow7").__class__.__module__) is not None
