"""A part's user-data columns survive its attachment: the assembly keeps as many as any part declares."""

from __future__ import annotations

import warnings

import mujoco
import numpy as np

from assembler.mjcf.compose import attach_at_world, new_assembly

PART = """\
<mujoco>
  <size nuser_actuator="4" nuser_jnt="2"/>
  <worldbody><body name="b"><joint name="j" user="7"/><geom size=".1"/></body></worldbody>
  <actuator><motor name="m" joint="j" user="1 2"/></actuator>
</mujoco>
"""


def test_a_parts_declared_user_columns_are_kept_in_the_assembly_and_nothing_warns() -> None:
    direct = mujoco.MjModel.from_xml_string(PART)
    assembly = new_assembly("<mujoco/>")
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        attach_at_world(assembly, mujoco.MjSpec.from_string(PART), "part_")
        model = assembly.compile()
    assert (model.nuser_actuator, model.nuser_jnt) == (direct.nuser_actuator, direct.nuser_jnt) == (4, 2)
    assert np.array_equal(model.actuator_user, direct.actuator_user)
    assert np.array_equal(model.jnt_user, direct.jnt_user)


def test_two_parts_with_different_column_counts_get_the_larger() -> None:
    assembly = new_assembly("<mujoco/>")
    attach_at_world(assembly, mujoco.MjSpec.from_string(PART), "first_")
    attach_at_world(
        assembly,
        mujoco.MjSpec.from_string(PART.replace('nuser_actuator="4"', 'nuser_actuator="6"')),
        "second_",
    )
    model = assembly.compile()
    assert model.nuser_actuator == 6
    assert model.actuator_user[0].tolist() == [1, 2, 0, 0, 0, 0]
