"""A small ROS-style package written to disk for the URDF tests: package.xml, a URDF with every trap
MuJoCo's import is known for, an STL cube and a COLLADA cube in millimetres."""

from __future__ import annotations

import struct
from pathlib import Path

CUBE_FACES = [(0, 1, 3), (0, 3, 2), (4, 6, 7), (4, 7, 5), (0, 4, 5), (0, 5, 1)]
CUBE_FACES += [(2, 3, 7), (2, 7, 6), (0, 2, 6), (0, 6, 4), (1, 5, 7), (1, 7, 3)]


def cube_vertices(edge: float) -> list[tuple[float, float, float]]:
    """The eight corners of a cube with one corner at the origin."""
    return [(x, y, z) for x in (0.0, edge) for y in (0.0, edge) for z in (0.0, edge)]


def write_stl(path: Path, edge: float = 0.1) -> Path:
    """A binary STL cube of the given edge (metres)."""
    vertices = cube_vertices(edge)
    data = bytearray(b"\0" * 80) + struct.pack("<I", len(CUBE_FACES))
    for face in CUBE_FACES:
        data += struct.pack("<3f", 0.0, 0.0, 0.0)
        for index in face:
            data += struct.pack("<3f", *vertices[index])
        data += b"\0\0"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_bytes(bytes(data))
    return path


def dae_text(edge_mm: float = 100.0, meter: str = "0.001") -> str:
    """A COLLADA cube whose coordinates are millimetres (``<unit meter="0.001">``), or other units."""
    points = " ".join(f"{v:g}" for vertex in cube_vertices(edge_mm) for v in vertex)
    triangles = " ".join(str(i) for face in CUBE_FACES for i in face)
    return f"""<?xml version="1.0" encoding="utf-8"?>
<COLLADA xmlns="http://www.collada.org/2005/11/COLLADASchema" version="1.4.1">
  <asset><unit name="millimeter" meter="{meter}"/><up_axis>Z_UP</up_axis></asset>
  <library_geometries>
    <geometry id="cube" name="cube">
      <mesh>
        <source id="cube-positions">
          <float_array id="cube-positions-array" count="24">{points}</float_array>
          <technique_common>
            <accessor source="#cube-positions-array" count="8" stride="3">
              <param name="X" type="float"/><param name="Y" type="float"/><param name="Z" type="float"/>
            </accessor>
          </technique_common>
        </source>
        <vertices id="cube-vertices"><input semantic="POSITION" source="#cube-positions"/></vertices>
        <triangles count="12"><input semantic="VERTEX" source="#cube-vertices" offset="0"/><p>{triangles}</p></triangles>
      </mesh>
    </geometry>
  </library_geometries>
  <library_visual_scenes>
    <visual_scene id="scene"><node id="cube-node"><instance_geometry url="#cube"/></node></visual_scene>
  </library_visual_scenes>
  <scene><instance_visual_scene url="#scene"/></scene>
</COLLADA>
"""


def write_dae(path: Path, edge_mm: float = 100.0) -> Path:
    """:func:`dae_text` written to ``path``."""
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(dae_text(edge_mm))
    return path


INERTIAL = (
    '<inertial><origin xyz="0 0 0.05"/><mass value="{mass}"/>'
    '<inertia ixx="0.01" iyy="0.01" izz="0.01" ixy="0" ixz="0" iyz="0"/></inertial>'
)

ARM_URDF = f"""<?xml version="1.0"?>
<robot name="my_arm">
  <link name="base_link">
    {INERTIAL.format(mass=2.0)}
    <visual><geometry><box size="0.2 0.2 0.1"/></geometry></visual>
    <collision><geometry><mesh filename="package://my_arm/meshes/cube.stl"/></geometry></collision>
  </link>
  <link name="link1">
    {INERTIAL.format(mass=1.0)}
    <visual><origin xyz="0 0 0.1"/><geometry><mesh filename="package://my_arm/meshes/cube.dae"/></geometry></visual>
    <collision><origin xyz="0 0 0.1"/><geometry><box size="0.05 0.05 0.05"/></geometry></collision>
  </link>
  <joint name="shoulder" type="revolute">
    <parent link="base_link"/><child link="link1"/><origin xyz="0 0 0.2"/><axis xyz="0 1 0"/>
    <limit lower="-1.0" upper="1.0" effort="5.0" velocity="2.0"/>
    <dynamics damping="0.2" friction="0.05"/>
  </joint>
  <link name="spinner">{INERTIAL.format(mass=0.5)}</link>
  <joint name="spin" type="continuous">
    <parent link="link1"/><child link="spinner"/><origin xyz="0 0 0.3"/><axis xyz="0 0 1"/>
  </joint>
  <link name="finger_a">{INERTIAL.format(mass=0.1)}</link>
  <joint name="finger_a_joint" type="prismatic">
    <parent link="spinner"/><child link="finger_a"/><origin xyz="0.05 0 0.1"/><axis xyz="1 0 0"/>
    <limit lower="0.0" upper="0.04" effort="10.0" velocity="0.1"/>
  </joint>
  <link name="finger_b">{INERTIAL.format(mass=0.1)}</link>
  <joint name="finger_b_joint" type="prismatic">
    <parent link="spinner"/><child link="finger_b"/><origin xyz="-0.05 0 0.1"/><axis xyz="1 0 0"/>
    <limit lower="-0.05" upper="0.05" effort="10.0" velocity="0.1"/>
    <mimic joint="finger_a_joint" multiplier="-1.0" offset="0.01"/>
  </joint>
  <link name="tool"/>
  <joint name="tool_joint" type="fixed"><parent link="spinner"/><child link="tool"/><origin xyz="0 0 0.15"/></joint>
</robot>
"""
"""A fixed base link with a visual box and a package:// STL collision mesh; a revolute joint with
effort, velocity and dynamics; a COLLADA visual mesh in millimetres; a continuous joint; two
prismatic fingers, the second a <mimic> of the first (multiplier -1, offset 0.01); a fixed tool link."""


def write_package(root: Path, name: str = "my_arm", urdf: str = ARM_URDF, declare: bool = True) -> Path:
    """A ROS package folder ``root/name`` (package.xml, urdf/, meshes/); returns the URDF's path.

    With ``declare``, the folder above ``root`` is made a spec repository that declares the package
    (``packages = ["root/name"]``), as a lab keeps a vendor's package beside its specs."""
    package = root / name
    package.mkdir(parents=True, exist_ok=True)
    if declare:
        (root.parent / "robot-assembler.toml").write_text(f'packages = ["{root.name}/{name}"]\n')
    (package / "package.xml").write_text(f"<package format='3'><name>{name}</name></package>")
    write_stl(package / "meshes" / "cube.stl")
    write_dae(package / "meshes" / "cube.dae")
    path = package / "urdf" / f"{name}.urdf"
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(urdf)
    return path


def line_of(text: str, needle: str) -> int:
    """The 1-based line of ``text`` where ``needle`` first appears (for exact messages)."""
    return next(number for number, line in enumerate(text.splitlines(), 1) if needle in line)
