"""Declared MJCF repairs (``mjcf_fixes``): files MuJoCo refuses or misreads become the intended model,
and a repair that no longer applies is reported instead of kept silently."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

import assembler
from assembler.errors import MjcfError, SpecError

FLAWED_GRIPPER = """\
<mujoco model="flawed">
  <asset>
    <mesh name="plate" vertex="0 0 0  1 0 0  0 1 0  0 0 1" scale="0.01 0.01 0.01"/>
    <mesh name="plate" vertex="0 0 0  2 0 0  0 2 0  0 0 2" scale="0.01 0.01 0.01"/>
  </asset>
  <default>
    <default class="finger" group="1">
      <joint damping="0.5"/>
    </default>
  </default>
  <worldbody>
    <body name="palm">
      <geom type="mesh" mesh="plate"/>
      <body name="finger" pos="0 0 0.02">
        <joint name="curl" class="finger" axis="1 0 0" range="0 1.5"/>
        <geom type="box" size="0.005 0.005 0.02" mass="0.01"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
"""Three flaws seen in robosuite's grippers: a repeated mesh name, an attribute MuJoCo's schema
refuses on <default>, and joint ranges in radians without <compiler angle="radian">."""

SPEC = """\
kind: gripper
name: Flawed
mjcf: flawed.xml
eef_body: palm
important_sites: {{}}
important_sensors: {{}}
{fixes}
"""

ALL_FIXES = """\
mjcf_fixes:
  - element: mesh
    keep_first_of_repeated_names: true
    why: the second plate repeats the first one's name
  - element: default
    remove: [group]
    why: group is not an attribute of default
  - element: compiler
    set: {angle: radian}
    why: the joint ranges are written in radians
"""


def _gripper(write: Callable[[str, str], Path], fixes: str) -> assembler.GripperModel:
    write("flawed.xml", FLAWED_GRIPPER)
    (cls,) = assembler.register_specs(write("flawed.yaml", SPEC.format(fixes=fixes)))
    part = cls(idn=0)
    assert isinstance(part, assembler.GripperModel)
    return part


def test_without_repairs_mujoco_refuses_the_file_and_the_error_points_at_mjcf_fixes(
    write: Callable[[str, str], Path],
) -> None:
    with pytest.raises(
        MjcfError,
        match=r"flawed.yaml:3:7: mjcf: .*flawed.xml:7: MuJoCo cannot read it: Schema violation: unrecognized "
        r"attribute: 'group'; correct the file \(a spec can declare a repair: mjcf_fixes\)$",
    ):
        _gripper(write, "").check()


def test_declared_repairs_give_the_intended_model(write: Callable[[str, str], Path]) -> None:
    model = _gripper(write, ALL_FIXES).compile_alone()
    assert model.nmesh == 1
    # 1.5 is read as radians, not degrees (0.026 rad), because of the compiler repair.
    assert model.jnt_range[0].tolist() == pytest.approx([0.0, 1.5])
    assert model.dof_damping[0] == pytest.approx(0.5)


def test_a_repair_that_changes_nothing_is_an_error(write: Callable[[str, str], Path]) -> None:
    stale = ALL_FIXES + "  - element: actuator\n    remove: [gear]\n    why: nothing here has a gear at all\n"
    with pytest.raises(
        MjcfError, match=r"mjcf_fixes on <actuator> changed nothing; delete it if the file is fixed"
    ):
        _gripper(write, stale).check()


def test_a_set_that_the_file_already_has_is_a_stale_repair(write: Callable[[str, str], Path]) -> None:
    already = (
        ALL_FIXES
        + "  - element: compiler\n    set: {angle: radian}\n    why: the same setting a second time\n"
    )
    with pytest.raises(MjcfError, match=r"mjcf_fixes on <compiler> changed nothing"):
        _gripper(write, already).check()


def test_a_repair_must_say_exactly_one_thing(write: Callable[[str, str], Path]) -> None:
    two_actions = "mjcf_fixes:\n  - element: default\n    remove: [group]\n    set: {a: b}\n    why: two actions at once\n"
    with pytest.raises(
        SpecError, match=r"mjcf_fixes\[0\].*give exactly one of keep_first_of_repeated_names, remove, set"
    ):
        _gripper(write, two_actions)


def test_repairs_are_refused_on_a_file_with_includes(write: Callable[[str, str], Path]) -> None:
    write("parts.xml", "<mujoco><default><geom rgba='1 0 0 1'/></default></mujoco>")
    write("flawed.xml", FLAWED_GRIPPER.replace("<asset>", '<include file="parts.xml"/>\n  <asset>'))
    (cls,) = assembler.register_specs(write("flawed.yaml", SPEC.format(fixes=ALL_FIXES)))
    with pytest.raises(MjcfError, match=r"mjcf_fixes cannot be used on a file that includes other files"):
        cls(idn=0).check()
