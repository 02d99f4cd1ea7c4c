"""Unnamed file-backed assets are named after their files, as MuJoCo names them, through every step."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import mujoco

import assembler

TETRA = "v 0 0 0\nv 0.1 0 0\nv 0 0.1 0\nv 0 0 0.1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"

UNNAMED_MESH_ROBOT = """\
<mujoco model="onshape_export">
  <compiler meshdir="assets"/>
  <asset>
    <mesh file="base_so101_v2.obj"/>
  </asset>
  <worldbody>
    <body name="base">
      <geom type="mesh" mesh="base_so101_v2" mass="0.5"/>
      <body name="link" pos="0 0 0.1">
        <joint name="pan" axis="0 0 1" range="-1 1"/>
        <geom type="mesh" mesh="base_so101_v2" mass="0.2"/>
        <body name="right_hand" pos="0 0 0.1"/>
      </body>
    </body>
  </worldbody>
</mujoco>
"""
"""As onshape-to-robot exports: meshes without names, referred to by their files' names."""


def test_an_unnamed_mesh_is_named_after_its_file_and_the_robot_builds(
    write: Callable[[str, str], Path],
) -> None:
    write("robot/assets/base_so101_v2.obj", TETRA)
    write("robot/so101.xml", UNNAMED_MESH_ROBOT)
    direct = mujoco.MjModel.from_xml_path(str(write("robot/so101.xml", UNNAMED_MESH_ROBOT)))
    (cls,) = assembler.register_specs(write("robot/so101.yaml", "name: So101\nmjcf: so101.xml\n"))

    model = cls(idn=0).get_model(cache=False)

    assert direct.mesh(0).name == "base_so101_v2"
    assert model.mesh(0).name == "robot0_base_so101_v2"
    meshes = {
        model.geom(g).dataid[0]
        for g in range(model.ngeom)
        if model.geom_type[g] == mujoco.mjtGeom.mjGEOM_MESH
    }
    assert meshes == {0}
