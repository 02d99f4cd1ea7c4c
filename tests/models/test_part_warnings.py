"""Warnings about a part point at the user's spec (file, line and its text), never at our code."""

from __future__ import annotations

import warnings
from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.errors import AssemblerWarning
from assembler.robosuite.grip_frames import add_grip_frames
from assembler.spec.fieldpath import FieldPath
from tests.models.test_gripper_defaults import BARE_HAND


def test_a_warning_names_the_spec_line_it_is_about(write: Callable[[str, str], Path]) -> None:
    write("bare.xml", BARE_HAND)
    spec = write("bare.yaml", "kind: gripper\nname: Bare\nmjcf: bare.xml\neef_body: palm\n")
    (cls,) = assembler.register_specs(spec)
    gripper = cls(idn=0)
    with pytest.warns(AssemblerWarning, match=r"Bare: robosuite looks a gripper up by body 'eef'") as caught:
        add_grip_frames(gripper, gripper.part_mjspec())
    (warning,) = caught
    assert (Path(warning.filename).name, warning.lineno) == ("bare.yaml", 4)
    shown = warnings.formatwarning(warning.message, warning.category, warning.filename, warning.lineno)
    assert shown.splitlines()[1].strip() == "eef_body: palm"  # the spec's text, not ours


def test_the_same_warning_is_shown_once(write: Callable[[str, str], Path]) -> None:
    write("bare.xml", BARE_HAND)
    (cls,) = assembler.register_specs(write("once.yaml", "kind: gripper\nname: Once\nmjcf: bare.xml\n"))
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("default")
        for _ in range(3):
            cls.warn(FieldPath(("mjcf",)), "Once: said once")
    assert len(caught) == 1
