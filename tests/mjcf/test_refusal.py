"""A part file MuJoCo refuses is refused, one line each: the spec's position, the MJCF file and line,
MuJoCo's own words and what to do; exit code 1 and nothing written.

Each case is the same small, valid robot with one defect. Every kind of name MuJoCo resolves is
covered: ``MjSpec.attach`` (and ``MjSpec.copy``) would drop the element silently instead (issue 12).
The robot has a mesh read from a file, so the check's stand-in meshes are on the path.
"""

from __future__ import annotations

from pathlib import Path

import pytest

import assembler
from assembler.cli import main
from assembler.errors import MjcfError
from tests.conftest import TETRAHEDRON_OBJ
from tests.models.semantics_robots import skin_file

ASSET, BODY, SECTIONS = "ASSET", "BODY", "SECTIONS"
"""Where a case puts its one element: among the assets, in the innermost body, at the end of the file."""

ROBOT = """\
<mujoco model="probe">
  <compiler angle="radian"/>
  <asset>
    <texture name="checker" type="2d" builtin="checker" width="8" height="8"/>
    <material name="paint" texture="checker"/>
    <mesh name="cube" file="cube.obj"/>
    <hfield name="ground" nrow="2" ncol="2" size="1 1 0.1 0.1"/>
    ASSET
  </asset>
  <default>
    <default class="arm"><joint damping="1"/></default>
  </default>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="mesh" mesh="cube" material="paint"/>
      <site name="base_site"/>
      <body name="link1" pos="0 0 0.2">
        <joint name="joint1" axis="0 0 1"/>
        <geom name="link1_col" size="0.05" mass="1"/>
        <site name="link1_site" pos="0 0.1 0"/>
        <body name="link2" pos="0 0 0.2">
          <joint name="joint2" axis="0 1 0"/>
          <geom name="link2_col" size="0.05" mass="1"/>
          <site name="link2_site" pos="0 0.1 0"/>
          BODY
        </body>
      </body>
    </body>
  </worldbody>
  SECTIONS
</mujoco>
"""
"""A valid robot with two hinge joints."""


REPAIR_HINT = " (a spec can declare a repair: mjcf_fixes)"


def _line_of(slot: str) -> int:
    return next(n for n, line in enumerate(ROBOT.splitlines(), 1) if line.strip() == slot)


def _robot_folder(folder: Path, slot: str, element: str) -> Path:
    """The robot with ``element`` at ``slot`` and its spec, written to ``folder``; the spec's path."""
    text = ROBOT
    for place in (ASSET, BODY, SECTIONS):
        text = text.replace(place, element if place == slot else "")
    (folder / "cube.obj").write_text(TETRAHEDRON_OBJ)
    (folder / "robot.xml").write_text(text)
    spec = folder / "robot.yaml"
    spec.write_text("name: Probe\nmjcf: robot.xml\n")
    return spec


# fmt: off
CASES = [
    # actuators: every transmission
    pytest.param(SECTIONS, '<actuator><motor name="a1" joint="nope"/></actuator>',
                 "{at}: MuJoCo refuses it: unknown transmission target 'nope' for actuator id = 0 (element 'a1'); correct the name or remove the element", id='actuator-joint'),
    pytest.param(SECTIONS, '<actuator><general name="a1" jointinparent="nope"/></actuator>',
                 "{at}: MuJoCo refuses it: unknown transmission target 'nope' for actuator id = 0 (element 'a1'); correct the name or remove the element", id='actuator-joint-in-parent'),
    pytest.param(SECTIONS, '<actuator><motor name="a1" tendon="nope"/></actuator>',
                 "{at}: MuJoCo refuses it: transmission target 'nope' not found in actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-tendon'),
    pytest.param(SECTIONS, '<actuator><motor name="a1" site="nope"/></actuator>',
                 "{at}: MuJoCo refuses it: transmission target 'nope' not found in actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-site'),
    pytest.param(SECTIONS, '<actuator><motor name="a1" site="link1_site" refsite="nope"/></actuator>',
                 "{at}: MuJoCo refuses it: reference site 'nope' not found for actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-refsite'),
    pytest.param(SECTIONS, '<actuator><adhesion name="a1" body="nope" ctrlrange="0 1"/></actuator>',
                 "{at}: MuJoCo refuses it: transmission target 'nope' not found in actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-body'),
    pytest.param(SECTIONS, '<actuator><general name="a1" cranksite="nope" slidersite="link1_site" cranklength="0.1"/></actuator>',
                 "{at}: MuJoCo refuses it: transmission target 'nope' not found in actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-cranksite'),
    pytest.param(SECTIONS, '<actuator><general name="a1" cranksite="link1_site" slidersite="nope" cranklength="0.1"/></actuator>',
                 "{at}: MuJoCo refuses it: base site 'nope' not found for actuator 0 (element 'a1'); correct the name or remove the element", id='actuator-slidersite'),
    pytest.param(SECTIONS, '<actuator><motor name="a1"/></actuator>',
                 "{at}: MuJoCo refuses it: missing transmission target for actuator (element 'a1'); correct the name or remove the element", id='actuator-no-target'),
    # sensors: each kind of object they measure or refer to
    pytest.param(SECTIONS, '<sensor><jointpos name="s1" joint="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-joint'),
    pytest.param(SECTIONS, '<sensor><tendonpos name="s1" tendon="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-tendon'),
    pytest.param(SECTIONS, '<sensor><actuatorfrc name="s1" actuator="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-actuator'),
    pytest.param(SECTIONS, '<sensor><touch name="s1" site="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-site'),
    pytest.param(SECTIONS, '<sensor><subtreecom name="s1" body="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-body'),
    pytest.param(SECTIONS, '<sensor><framepos name="s1" objtype="geom" objname="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-frame-object'),
    pytest.param(SECTIONS, '<sensor><framepos name="s1" objtype="body" objname="link1" reftype="site" refname="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of object (element 's1'); correct the name or remove the element", id='sensor-frame-reference'),
    pytest.param(SECTIONS, '<sensor><distance name="s1" geom1="nope" geom2="link1_col"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-geom'),
    pytest.param(SECTIONS, '<sensor><contact name="s1" body1="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-contact-body'),
    pytest.param(SECTIONS, '<sensor><camprojection name="s1" site="link1_site" camera="nope"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of object (element 's1'); correct the name or remove the element", id='sensor-camera'),
    pytest.param(SECTIONS, '<sensor><user name="s1" objtype="xbody" objname="nope" dim="1"/></sensor>',
                 "{at}: MuJoCo refuses it: unrecognized name 'nope' of sensorized object (element 's1'); correct the name or remove the element", id='sensor-user-object'),
    pytest.param(SECTIONS, '<sensor><ballquat name="s1" joint="joint1"/></sensor>',
                 "{at}: MuJoCo refuses it: joint must be ball in sensor (element 's1'); correct the file", id='sensor-joint-kind'),
    # tendons: every kind of wrap
    pytest.param(SECTIONS, '<tendon><fixed name="t1"><joint joint="nope" coef="1"/></fixed></tendon>',
                 "{at}: MuJoCo refuses it: joint 'nope' not found in tendon 0, wrap 0; correct the name or remove the element", id='tendon-fixed-joint'),
    pytest.param(SECTIONS, '<tendon><spatial name="t1"><site site="base_site"/><site site="nope"/></spatial></tendon>',
                 "{at}: MuJoCo refuses it: site 'nope' not found in wrap 1; correct the name or remove the element", id='tendon-spatial-site'),
    pytest.param(SECTIONS, '<tendon><spatial name="t1"><site site="base_site"/><geom geom="nope"/><site site="link2_site"/></spatial></tendon>',
                 "{at}: MuJoCo refuses it: geom 'nope' not found in tendon 0, wrap 1; correct the name or remove the element", id='tendon-spatial-geom'),
    pytest.param(SECTIONS, '<tendon><spatial name="t1"><site site="base_site"/><geom geom="link1_col" sidesite="nope"/><site site="link2_site"/></spatial></tendon>',
                 "{at}: MuJoCo refuses it: side site 'nope' not found in tendon 0, wrap 1 (element 'link1_col'); correct the name or remove the element", id='tendon-side-site'),
    pytest.param(SECTIONS, '<tendon><spatial name="t1" material="nope"><site site="base_site"/><site site="link2_site"/></spatial></tendon>',
                 "{at}: MuJoCo refuses it: material 'nope' not found in tendon 0 (element 't1'); correct the name or remove the element", id='tendon-material'),
    # equalities: bodies, sites, joints, tendons
    pytest.param(SECTIONS, '<equality><connect name="e1" body1="nope" anchor="0 0 0"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint (element 'e1'); correct the name or remove the element", id='equality-connect-body'),
    pytest.param(SECTIONS, '<equality><weld name="e1" body1="link1" body2="nope"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint 0 (element 'e1'); correct the name or remove the element", id='equality-weld-body'),
    pytest.param(SECTIONS, '<equality><weld name="e1" site1="link1_site" site2="nope"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint 0 (element 'e1'); correct the name or remove the element", id='equality-weld-site'),
    pytest.param(SECTIONS, '<equality><joint name="e1" joint1="joint1" joint2="nope"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint 0 (element 'e1'); correct the name or remove the element", id='equality-joint'),
    pytest.param(SECTIONS, '<equality><tendon name="e1" tendon1="nope"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint (element 'e1'); correct the name or remove the element", id='equality-tendon'),
    pytest.param(SECTIONS, '<equality><joint joint1="nope"/></equality>',
                 "{at}: MuJoCo refuses it: unknown element 'nope' in equality constraint; correct the name or remove the element", id='equality-unnamed'),
    # contact pairs and excludes
    pytest.param(SECTIONS, '<contact><pair name="p1" geom1="link1_col" geom2="nope"/></contact>',
                 "{at}: MuJoCo refuses it: geom 'nope' not found in collision 0 (element 'p1'); correct the name or remove the element", id='pair-geom'),
    pytest.param(SECTIONS, '<contact><exclude name="x1" body1="link1" body2="nope"/></contact>',
                 "{at}: MuJoCo refuses it: body 'nope' not found in bodypair 0 (element 'x1'); correct the name or remove the element", id='exclude-body'),
    # assets, and what cameras and lights aim at
    pytest.param(BODY, '<geom name="g3" size="0.05" material="nope"/>',
                 "{at}: MuJoCo refuses it: material 'nope' not found in geom 3 (element 'g3'); correct the name or remove the element", id='geom-material'),
    pytest.param(BODY, '<geom name="g3" type="mesh" mesh="nope"/>',
                 "{at}: MuJoCo refuses it: mesh 'nope' not found in geom 3 (element 'g3'); correct the name or remove the element", id='geom-mesh'),
    pytest.param(BODY, '<geom name="g3" type="hfield" hfield="nope"/>',
                 "{at}: MuJoCo refuses it: hfield 'nope' not found in geom 3 (element 'g3'); correct the name or remove the element", id='geom-hfield'),
    pytest.param(BODY, '<geom name="g3" type="mesh"/>',
                 "{at}: MuJoCo refuses it: mesh geom 'g3' (id = 3) must have valid meshid; correct the name or remove the element", id='mesh-geom-without-mesh'),
    pytest.param(BODY, '<site name="s3" material="nope"/>',
                 "{at}: MuJoCo refuses it: material 'nope' not found in site 3 (element 's3'); correct the name or remove the element", id='site-material'),
    pytest.param(ASSET, '<material name="rust" texture="nope"/>',
                 "{at}: MuJoCo refuses it: texture 'nope' not found in material 1 (element 'rust'); correct the name or remove the element", id='material-texture'),
    pytest.param(ASSET, '<skin name="sk" vertex="0 0 0 1 0 0 0 1 0" face="0 1 2"><bone body="nope" bindpos="0 0 0" bindquat="1 0 0 0" vertid="0 1 2" vertweight="1 1 1"/></skin>',
                 "{at}: MuJoCo refuses it: unknown body 'nope' in skin (element 'sk'); correct the name or remove the element", id='skin-bone'),
    pytest.param(BODY, '<camera name="c1" mode="targetbody" target="nope"/>',
                 "{at}: MuJoCo refuses it: unknown target body in camera (element 'c1'); correct the name or remove the element", id='camera-target'),
    pytest.param(BODY, '<light name="l1" mode="targetbody" target="nope"/>',
                 "{at}: MuJoCo refuses it: unknown target body in light (element 'l1'); correct the name or remove the element", id='light-target'),
    pytest.param(BODY, '<light name="l1" texture="nope"/>',
                 "{at}: MuJoCo refuses it: unknown texture in light (element 'l1'); correct the name or remove the element", id='light-texture'),
    # custom data
    pytest.param(SECTIONS, '<custom><tuple name="tp"><element objtype="body" objname="nope"/></tuple></custom>',
                 "{at}: MuJoCo refuses it: unrecognized object 'nope' in tuple 0 (element 'tp'); correct the name or remove the element", id='tuple-object'),
    # keyframes: sizes follow the model (MuJoCo gives no line)
    pytest.param(SECTIONS, '<keyframe><key name="k1" qpos="0 0 0"/></keyframe>',
                 "{file}: MuJoCo refuses it: keyframe 'k1': invalid qpos size, expected 2, got 3; correct the file", id='keyframe-qpos-size'),
    pytest.param(SECTIONS, '<keyframe><key name="k1" ctrl="1"/></keyframe>',
                 "{file}: MuJoCo refuses it: keyframe 0: invalid ctrl size, expected length 0 (element 'k1'); correct the file", id='keyframe-ctrl-size'),
    # default classes, resolved while MuJoCo reads the file
    pytest.param(BODY, '<geom name="g3" size="0.05" class="nope"/>',
                 "{at}: MuJoCo cannot read it: unknown default class name 'nope'; correct the name or remove the element", id='default-class'),
    pytest.param(BODY, '<body name="link3" childclass="nope"><geom size="0.05"/></body>',
                 '{at}: MuJoCo cannot read it: unknown default childclass; correct the name or remove the element', id='childclass'),
    pytest.param(BODY, '<frame childclass="nope"><geom size="0.05"/></frame>',
                 '{at}: MuJoCo cannot read it: unknown default childclass; correct the name or remove the element', id='frame-childclass'),
    # not a reference, but refused all the same
    pytest.param(BODY, '<body name="link3"><joint name="joint3" limited="true" range="1 0"/><geom size="0.05"/></body>',
                 "{at}: MuJoCo refuses it: range[0] should be smaller than range[1] in joint (element 'joint3'); correct the file", id='joint-range'),
]
# fmt: on


@pytest.mark.parametrize(("slot", "element", "expected"), CASES)
def test_a_file_mujoco_refuses_is_refused_with_its_line_and_nothing_is_written(
    tmp_path: Path, capsys: pytest.CaptureFixture[str], slot: str, element: str, expected: str
) -> None:
    spec = _robot_folder(tmp_path, slot, element)
    xml, out = tmp_path / "robot.xml", tmp_path / "out.xml"
    code = main(["build", str(spec), "-o", str(out)])
    message = expected.format(at=f"{xml}:{_line_of(slot)}", file=xml)
    assert (code, capsys.readouterr().err) == (1, f"{spec}:2:7: mjcf: {message}{REPAIR_HINT}\n")
    assert not out.exists()


def test_validate_refuses_the_file_too(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    spec = _robot_folder(tmp_path, SECTIONS, '<sensor><touch name="s1" site="nope"/></sensor>')
    assert main(["validate", str(spec)]) == 1
    assert (
        "robot.xml:30: MuJoCo refuses it: unrecognized name 'nope' of sensorized object"
        in capsys.readouterr().err
    )


def test_the_robot_without_a_defect_builds_with_every_element(tmp_path: Path) -> None:
    spec = _robot_folder(tmp_path, SECTIONS, '<sensor><touch name="s1" site="link1_site"/></sensor>')
    (cls,) = assembler.register_specs(spec)
    model = cls(idn=0).get_model()
    assert (model.nsensor, model.sensor("robot0_s1").objid[0]) == (1, model.site("robot0_link1_site").id)


REPAIRED = """\
<?xml version="1.0"?>
<!-- a robot whose <compiler> its spec repairs: MuJoCo reads the repaired text, -->
<!-- whose lines differ from the file's (no declaration, no comments, one-line attributes) -->
<mujoco model="repaired">
  <compiler angle="degree"/>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="box" size="0.1
                                            0.1
                                            0.1"/>
      <body name="link1">
        <joint name="joint1"/>
        <geom name="link1_col" size="0.05"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor name="a1" joint="joint9"/>
  </actuator>
</mujoco>
"""

REPAIR = """\
name: Repaired
mjcf: repaired.xml
mjcf_fixes:
  - element: compiler
    why: the file gives radians but declares degrees
    set: {angle: radian}
"""


def test_a_repaired_file_is_refused_at_the_line_of_the_file_on_disk(tmp_path: Path) -> None:
    (tmp_path / "repaired.xml").write_text(REPAIRED)
    (tmp_path / "repaired.yaml").write_text(REPAIR)
    (cls,) = assembler.register_specs(tmp_path / "repaired.yaml")
    line = REPAIRED.splitlines().index('    <motor name="a1" joint="joint9"/>') + 1
    expected = (
        f"{tmp_path}/repaired.yaml:2:7: mjcf: {tmp_path}/repaired.xml:{line}: MuJoCo refuses it: unknown "
        "transmission target 'joint9' for actuator id = 0 (element 'a1'); correct the name or remove "
        f"the element{REPAIR_HINT}"
    )
    with pytest.raises(MjcfError) as error:
        cls(idn=0).check()
    assert (line, str(error.value)) == (18, expected)


def test_an_element_from_an_included_file_is_named_since_mujoco_gives_no_line(tmp_path: Path) -> None:
    (tmp_path / "actuators.xml").write_text(
        '<mujoco><actuator><motor name="a1" joint="joint9"/></actuator></mujoco>'
    )
    (tmp_path / "main.xml").write_text(
        '<mujoco><include file="actuators.xml"/><worldbody><body name="base"><joint name="joint1"/>'
        '<geom size="0.1"/></body></worldbody></mujoco>'
    )
    (tmp_path / "main.yaml").write_text("name: Included\nmjcf: main.xml\n")
    (cls,) = assembler.register_specs(tmp_path / "main.yaml")
    with pytest.raises(MjcfError) as error:
        cls(idn=0).check()
    assert str(error.value) == (
        f"{tmp_path}/main.yaml:2:7: mjcf: {tmp_path}/main.xml: MuJoCo refuses it: unknown transmission "
        "target 'joint9' for actuator id = 0 (element 'a1'); correct the name or remove the element"
        f"{REPAIR_HINT}"
    )


def test_a_moving_body_left_massless_for_the_assembly_to_fill_passes_the_file_check(tmp_path: Path) -> None:
    # robosuite's NullMobileBase: its support has no mass until a robot stands on it.
    spec = _robot_folder(tmp_path, BODY, '<body name="carrier"><joint name="joint3"/></body>')
    (cls,) = assembler.register_specs(spec)
    robot = cls(idn=0)  # the file check passes...
    with pytest.raises(MjcfError, match=r"MuJoCo cannot compile the assembly: mass and inertia of moving"):
        robot.get_model()  # ...and the assembly, with nothing on the body, is refused all the same


def test_a_skin_file_whose_bone_names_a_missing_body_is_refused(tmp_path: Path) -> None:
    # The check stands in for mesh and texture files, but reads skin files: they name bodies.
    (tmp_path / "sleeve.skn").write_bytes(skin_file([("link1", [0, 1]), ("nope", [2])]))
    spec = _robot_folder(tmp_path, ASSET, '<skin name="sleeve" file="sleeve.skn"/>')
    (cls,) = assembler.register_specs(spec)
    with pytest.raises(MjcfError) as error:
        cls(idn=0).check()
    assert str(error.value) == (
        f"{spec}:2:7: mjcf: {tmp_path}/robot.xml:{_line_of(ASSET)}: MuJoCo refuses it: unknown body 'nope' "
        f"in skin (element 'sleeve'); correct the name or remove the element{REPAIR_HINT}"
    )
