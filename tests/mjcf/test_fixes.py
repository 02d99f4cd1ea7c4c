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
        SpecError,
        match=r"mjcf_fixes\[0\].*give exactly one of keep_first_of_repeated_names, remove, set, delete",
    ):
        _gripper(write, two_actions)


def test_repairs_apply_to_the_files_a_file_includes(write: Callable[[str, str], Path]) -> None:
    included = (
        FLAWED_GRIPPER.split("<worldbody>")[0].replace('<mujoco model="flawed">', "<mujoco>") + "</mujoco>"
    )
    write("parts.xml", included)
    main = FLAWED_GRIPPER.split("<asset>")[0] + '<include file="parts.xml"/>\n  <worldbody>'
    write("flawed.xml", main + FLAWED_GRIPPER.split("<worldbody>")[1])
    (cls,) = assembler.register_specs(write("flawed.yaml", SPEC.format(fixes=ALL_FIXES)))

    model = cls(idn=0).compile_alone()

    assert model.nmesh == 1  # the repeated mesh name and the <default> attribute were in parts.xml
    assert model.dof_damping[0] == pytest.approx(0.5)


FETCH_LIKE = """\
<mujoco model="fetchish">
  <worldbody>
    <body name="robot0:mocap" mocap="true" pos="0 0 0.5">
      <geom type="box" size="0.005 0.005 0.005" contype="0" conaffinity="0" rgba="0 0.5 0 0.7"/>
    </body>
    <body name="base">
      <geom type="box" size="0.1 0.1 0.1" mass="5"/>
      <body name="link" pos="0 0 0.2">
        <joint name="lift" axis="0 0 1" range="-1 1"/>
        <geom type="box" size="0.05 0.05 0.05" mass="1"/>
        <body name="right_hand" pos="0 0 0.1"/>
      </body>
    </body>
  </worldbody>
  <equality>
    <weld body1="robot0:mocap" body2="right_hand" solref="0.02 1"/>
  </equality>
</mujoco>
"""
"""As gymnasium-robotics' Fetch: a mocap body beside the robot, welded to its hand."""

CUT_MOCAP = """\
mjcf_fixes:
  - element: body
    where: {name: "robot0:mocap"}
    delete: true
    why: the mocap body drives the hand in gymnasium's tasks; robosuite's controllers drive the joints
  - element: weld
    where: {body1: "robot0:mocap"}
    delete: true
    why: the weld holds the hand to the mocap body deleted above
"""


def test_a_repair_deletes_the_elements_it_selects(write: Callable[[str, str], Path]) -> None:
    write("fetchish.xml", FETCH_LIKE)
    spec = f"name: Fetchish\nmjcf: fetchish.xml\n{CUT_MOCAP}"
    (cls,) = assembler.register_specs(write("fetchish.yaml", spec))

    model = cls(idn=0).get_model(cache=False)

    assert [model.body(b).name for b in range(model.nbody)] == [
        "world",
        "robot0_base",
        "robot0_link",
        "robot0_right_hand",
    ]
    assert model.neq == 0 and model.nmocap == 0


def test_a_deletion_that_selects_nothing_is_a_stale_repair(write: Callable[[str, str], Path]) -> None:
    write("fetchish.xml", FETCH_LIKE)
    spec = f"name: Fetchish\nmjcf: fetchish.xml\n{CUT_MOCAP.replace('body1', 'body2')}"
    (cls,) = assembler.register_specs(write("fetchish.yaml", spec))
    with pytest.raises(MjcfError, match=r"mjcf_fixes on <weld> changed nothing"):
        cls(idn=0).check()
