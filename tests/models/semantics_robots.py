"""Valid robot MJCF files with varied features, for tests/models/test_semantics_preservation.py.

Each file is one arm (a static root, three hinged links and a tip) with the features of its case
filled into named slots: every actuator type and transmission, fixed and spatial tendons, every
equality type, sensors of many types, default classes, childclass, frames, cameras, lights, pairs,
excludes, assets, custom data, model-wide sections and more.
"""

from __future__ import annotations

import struct

ARM = """\
<mujoco model="{name}">
  {head}
  <asset>
    <texture name="grid" type="2d" builtin="checker" width="16" height="16" rgb1=".2 .3 .4" rgb2=".8 .8 .8"/>
    <material name="steel" texture="grid" specular="0.3" rgba=".7 .7 .7 1"/>
    {asset}
  </asset>
  <default>
    {default}
  </default>
  <worldbody>
    {world}
    <body name="base" pos="0 0 0.1" {base_attr}>
      {base}
      <geom name="base_col" type="cylinder" size="0.06 0.05" mass="2"/>
      <geom name="base_vis" type="cylinder" size="0.061 0.05" group="1" contype="0" conaffinity="0"
            material="steel"/>
      <site name="base_site" size="0.01"/>
      <body name="link1" pos="0 0 0.1" {link1_attr}>
        <joint name="joint1" axis="0 0 1" range="-3 3" {joint1_attr}/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <geom name="link1_vis" type="capsule" fromto="0 0 0 0.3 0 0" size="0.031" group="1"
              contype="0" conaffinity="0" rgba=".9 .5 .1 1"/>
        <site name="link1_site" pos="0.15 0.04 0" size="0.01"/>
        {link1}
        <body name="link2" pos="0.3 0 0">
          <joint name="joint2" axis="0 1 0" range="-2 2"/>
          <geom name="link2_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.025" mass="0.5"/>
          <site name="link2_site" pos="0.15 0.04 0" size="0.01"/>
          {link2}
          <body name="link3" pos="0.3 0 0">
            <joint name="joint3" axis="1 0 0" range="-1.5 1.5"/>
            <geom name="link3_col" type="box" size="0.03 0.02 0.02" mass="0.2"/>
            <site name="tip" pos="0.05 0 0" size="0.01"/>
            {tip}
          </body>
        </body>
      </body>
    </body>
  </worldbody>
  {sections}
</mujoco>
"""

SLOTS = ("head", "asset", "default", "world", "base_attr", "base", "link1_attr", "joint1_attr", "link1")
SLOTS += ("link2", "tip", "sections")

FINGERS = """
<body name="finger_left" pos="0.06 0.02 0">
  <joint name="finger_left_slide" type="slide" axis="0 1 0" range="0 0.04"/>
  <geom name="finger_left_col" type="box" size="0.01 0.005 0.02" mass="0.05"/>
</body>
<body name="finger_right" pos="0.06 -0.02 0">
  <joint name="finger_right_slide" type="slide" axis="0 -1 0" range="0 0.04"/>
  <geom name="finger_right_col" type="box" size="0.01 0.005 0.02" mass="0.05"/>
</body>"""

BALL_TIP = """
<body name="wrist" pos="0.06 0 0">
  <joint name="wrist_ball" type="ball" range="0 1.2"/>
  <geom name="wrist_col" type="sphere" size="0.02" mass="0.1"/>
  <site name="wrist_site" pos="0.02 0 0" size="0.005"/>
</body>"""

CUBE_OBJ = "v 0 0 0\nv 0.05 0 0\nv 0 0.05 0\nv 0 0 0.05\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
"""A mesh file some cases read (written next to the MJCF)."""


def skin_file(bones: list[tuple[str, list[int]]]) -> bytes:
    """A MuJoCo skin file (.skn) of one triangle; each bone names a body and the vertices it moves."""
    data = struct.pack("4i", 3, 0, 1, len(bones)) + struct.pack("9f", 0, 0, 0, 0.3, 0, 0, 0, 0.3, 0)
    data += struct.pack("3i", 0, 1, 2)
    for body, vertices in bones:
        data += body.encode().ljust(40, b"\0") + struct.pack("7f", 0, 0, -0.2, 1, 0, 0, 0)
        data += struct.pack(
            f"i{len(vertices)}i{len(vertices)}f", len(vertices), *vertices, *[1.0] * len(vertices)
        )
    return data


SLEEVE_SKN = skin_file([("link1", [0, 1]), ("link2", [2])])
"""A skin file some cases read (written next to the MJCF)."""

CASES: dict[str, dict[str, str]] = {
    "motors": {
        "sections": """<actuator>
          <motor name="m1" joint="joint1" gear="50" ctrlrange="-1 1" ctrllimited="true"/>
          <motor name="m2" joint="joint2" gear="30" forcerange="-20 20" forcelimited="true"/>
          <motor name="m3" joint="joint3"/></actuator>""",
    },
    "position-actuators": {
        "sections": """<actuator>
          <position name="p1" joint="joint1" kp="200" kv="10" ctrlrange="-3 3"/>
          <position name="p2" joint="joint2" kp="100" dampratio="1" ctrlrange="-2 2"/>
          <position name="p3" joint="joint3" kp="50" timeconst="0.05"/></actuator>""",
    },
    "velocity-and-intvelocity": {
        "sections": """<actuator>
          <velocity name="v1" joint="joint1" kv="20"/>
          <intvelocity name="iv2" joint="joint2" kp="80" actrange="-2 2"/>
          <intvelocity name="iv3" joint="joint3" kp="30" kv="2" actrange="-1 1" ctrlrange="-1 1"/></actuator>""",
    },
    "damper-and-cylinder": {
        "sections": """<actuator>
          <damper name="d1" joint="joint1" kv="5" ctrlrange="0 1"/>
          <cylinder name="c2" joint="joint2" area="0.01" timeconst="0.1" bias="0 -100 0"/></actuator>""",
    },
    "muscles": {
        "sections": """<tendon><fixed name="flexor"><joint joint="joint2" coef="0.05"/></fixed></tendon>
        <actuator>
          <muscle name="mus_tendon" tendon="flexor" force="100" lengthrange="0.01 0.2"/>
          <muscle name="mus_joint" joint="joint3" force="20" range="0.7 1.3" lmin="0.4" lmax="1.7"/>
        </actuator>""",
    },
    "adhesion-and-general": {
        "tip": '<geom name="pad" type="box" pos="0.04 0 0" size="0.01 0.02 0.02" mass="0.01"/>',
        "sections": """<actuator>
          <adhesion name="stick" body="link3" ctrlrange="0 1" gain="5"/>
          <general name="g1" joint="joint1" dyntype="filter" dynprm="0.1" gaintype="affine"
                   gainprm="10 -1 -0.5" biastype="affine" biasprm="0 -10 -1" actlimited="true"
                   actrange="-1 1"/>
          <general name="g2" joint="joint2" dyntype="integrator" gaintype="fixed" gainprm="3"/>
        </actuator>""",
    },
    "site-driven-actuators": {
        "sections": """<actuator>
          <motor name="push" site="tip" gear="0 0 1 0 0 0"/>
          <motor name="twist" site="tip" refsite="base_site" gear="0 0 0 0 0 1"/>
          <position name="reach" site="tip" refsite="base_site" kp="30" gear="1 0 0 0 0 0"/>
        </actuator>""",
    },
    "tendon-driven-actuators": {
        "sections": """<tendon>
          <fixed name="coupling" limited="true" range="-0.5 0.5" stiffness="3" damping="0.2">
            <joint joint="joint2" coef="1"/><joint joint="joint3" coef="-0.5"/>
          </fixed></tendon>
        <actuator><motor name="pull" tendon="coupling" gear="4"/>
          <position name="hold" tendon="coupling" kp="40"/></actuator>""",
    },
    "slider-crank-and-joint-in-parent": {
        "tip": BALL_TIP,
        "link1": '<site name="crank" pos="0.1 0 0.03" size="0.005"/>',
        "sections": """<actuator>
          <general name="crankdrive" cranksite="crank" slidersite="base_site" cranklength="0.12"/>
          <general name="inparent" jointinparent="wrist_ball" gear="0 0 1"/></actuator>""",
    },
    "spatial-tendons": {
        "link1": '<geom name="pulley_wheel" type="cylinder" pos="0.3 0 0" size="0.02 0.01" zaxis="0 1 0"'
        ' group="3" contype="0" conaffinity="0"/><site name="side" pos="0.3 0 0.04" size="0.005"/>',
        "sections": """<tendon>
          <spatial name="string" width="0.004" rgba="1 0 0 1" limited="true" range="0 0.9">
            <site site="base_site"/><site site="link1_site"/>
            <geom geom="pulley_wheel" sidesite="side"/><site site="link2_site"/>
            <pulley divisor="2"/><site site="link2_site"/><site site="tip"/>
          </spatial>
          <spatial name="strap" material="steel" springlength="0.3" stiffness="10">
            <site site="link1_site"/><site site="tip"/></spatial>
        </tendon>""",
    },
    "equality-connect-and-weld": {
        "tip": FINGERS,
        "sections": """<equality>
          <connect name="hinge_pin" body1="finger_left" body2="link3" anchor="0 0 0"/>
          <weld name="glue" body1="finger_right" body2="link3" solref="0.01 1" torquescale="2"/>
          <weld name="site_glue" site1="tip" site2="link2_site" active="false"/>
        </equality>""",
    },
    "equality-joint-and-tendon": {
        "tip": FINGERS,
        "sections": """<tendon>
          <fixed name="left_t"><joint joint="finger_left_slide" coef="1"/></fixed>
          <fixed name="right_t"><joint joint="finger_right_slide" coef="1"/></fixed></tendon>
        <equality>
          <joint name="mirror" joint1="finger_right_slide" joint2="finger_left_slide" polycoef="0 1 0 0 0"/>
          <joint name="lock" joint1="joint3" polycoef="0.1 0 0 0 0" active="false"/>
          <tendon name="tie" tendon1="left_t" tendon2="right_t" polycoef="0 2 0 0 0"/>
        </equality>
        <actuator><position name="grip" joint="finger_left_slide" kp="100" ctrlrange="0 0.04"/></actuator>""",
    },
    "joint-and-actuator-sensors": {
        "sections": """<actuator><motor name="m1" joint="joint1"/><velocity name="v2" joint="joint2" kv="3"/></actuator>
        <tendon><fixed name="t23"><joint joint="joint2" coef="1"/><joint joint="joint3" coef="1"/></fixed></tendon>
        <sensor>
          <jointpos name="q1" joint="joint1"/><jointvel name="dq2" joint="joint2" noise="0.01"/>
          <jointactuatorfrc name="jaf1" joint="joint1"/><actuatorpos name="ap1" actuator="m1"/>
          <actuatorvel name="av2" actuator="v2"/><actuatorfrc name="af2" actuator="v2" cutoff="5"/>
          <tendonpos name="tp" tendon="t23"/><tendonvel name="tv" tendon="t23"/>
          <jointlimitpos name="jl1" joint="joint1"/><jointlimitfrc name="jlf2" joint="joint2"/>
        </sensor>""",
    },
    "site-sensors": {
        "sections": """<sensor>
          <touch name="touch" site="tip"/><accelerometer name="acc" site="tip"/>
          <velocimeter name="vel" site="tip"/><gyro name="gyro" site="tip"/>
          <force name="f" site="link2_site"/><torque name="t" site="link2_site"/>
          <magnetometer name="mag" site="tip"/><rangefinder name="rf" site="tip"/>
        </sensor>""",
    },
    "frame-and-subtree-sensors": {
        "sections": """<sensor>
          <framepos name="fp" objtype="site" objname="tip" reftype="body" refname="link1"/>
          <framequat name="fq" objtype="body" objname="link3"/><framexaxis name="fx" objtype="geom" objname="link3_col"/>
          <framelinvel name="flv" objtype="site" objname="tip"/><frameangvel name="fav" objtype="xbody" objname="link2"/>
          <framelinacc name="fla" objtype="body" objname="link3"/><frameangacc name="faa" objtype="body" objname="link3"/>
          <subtreecom name="com" body="link1"/><subtreelinvel name="slv" body="link1"/>
          <subtreeangmom name="sam" body="link1"/>
        </sensor>""",
    },
    "ball-geometry-and-user-sensors": {
        "tip": BALL_TIP,
        "link1": '<camera name="eye" pos="0 0 0.2" mode="fixed" resolution="64 48"/>',
        "sections": """<sensor>
          <ballquat name="bq" joint="wrist_ball"/><ballangvel name="bav" joint="wrist_ball"/>
          <distance name="gap" geom1="link1_col" geom2="wrist_col"/><normal name="nrm" body1="link1" body2="wrist"/>
          <fromto name="ft" geom1="base_col" geom2="link3_col"/><clock name="time"/>
          <user name="custom" objtype="site" objname="tip" dim="2" datatype="real" needstage="pos"/>
          <camprojection name="seen" site="tip" camera="eye"/>
          <contact name="touching" body1="link3" reduce="mindist" num="2" data="found force"/>
        </sensor>""",
    },
    "default-classes": {
        "default": """<default class="arm">
            <joint damping="2" armature="0.1" frictionloss="0.05"/>
            <geom rgba=".1 .2 .3 1" friction="0.8 0.01 0.001"/>
            <motor ctrlrange="-2 2" ctrllimited="true" gear="20"/>
            <site size="0.02" rgba="0 1 0 1"/>
            <default class="wrist"><joint armature="0.02" damping="0.5"/><geom condim="4"/></default>
          </default>""",
        "joint1_attr": 'class="arm"',
        "tip": '<geom name="tip_pad" class="wrist" size="0.01" pos="0.04 0 0" mass="0.01"/>'
        '<site name="tip2" class="arm"/>',
        "sections": '<actuator><motor name="m1" joint="joint1" class="arm"/>'
        '<motor name="m3" joint="joint3" class="arm" gear="5"/></actuator>',
    },
    "childclass": {
        "default": """<default class="soft"><joint stiffness="3" springref="0.2" damping="1"/>
            <geom solref="0.03 1" solimp="0.8 0.9 0.01 0.5 2"/>
            <default class="stiff"><joint stiffness="30"/></default></default>""",
        "link1_attr": 'childclass="soft"',
        "link2": '<body name="link2b" pos="0 0.1 0" childclass="stiff"><joint name="extra"/>'
        '<geom name="link2b_col" size="0.02" mass="0.1"/></body>',
    },
    "frames": {
        "default": '<default class="framed"><geom rgba="1 1 0 1" group="2"/></default>',
        "link1": """<frame name="mount" pos="0.1 0 0.05" euler="0 0.3 0" childclass="framed">
            <geom name="framed_box" type="box" size="0.01 0.01 0.01" mass="0.01"/>
            <site name="framed_site" pos="0 0 0.02"/>
            <frame pos="0 0.02 0" quat="0.7071 0 0 0.7071">
              <body name="bracket"><geom name="bracket_col" type="sphere" size="0.01" mass="0.01"/></body>
            </frame>
          </frame>""",
    },
    "cameras": {
        "world": '<camera name="overview" pos="1.5 0 1" xyaxes="0 1 0 -0.5 0 1" fovy="60"/>',
        "base": '<camera name="robotview" pos="1 0 0.5" xyaxes="0 1 0 -0.4 0 1"/>',
        "link2": '<camera name="follow" mode="track" pos="0 -1 0.5" xyaxes="1 0 0 0 0.5 1"/>'
        '<camera name="comcam" mode="trackcom" pos="0 -1 0.3"/>',
        "tip": '<camera name="aim" mode="targetbody" target="link1" pos="0 0 0.3"/>'
        '<camera name="aimcom" mode="targetbodycom" target="link2" pos="0.2 0 0.3" ipd="0.05"/>',
    },
    "lights": {
        "world": '<light name="sun" directional="true" pos="0 0 3" dir="0 0 -1" castshadow="false"/>',
        "base": '<light name="lamp" pos="0 0 1" dir="0 0 -1" cutoff="40" exponent="5" attenuation="1 0.1 0"/>',
        "tip": '<light name="torch" mode="targetbody" target="link1" pos="0 0 0.2" diffuse=".5 .5 .5"/>',
    },
    "pairs-and-excludes": {
        "sections": """<contact>
          <pair name="elbow_base" geom1="link2_col" geom2="base_col" condim="6" friction="1 1 0.01 0.001 0.001"
                solref="0.02 1" margin="0.001"/>
          <pair geom1="link3_col" geom2="link1_col" solreffriction="0.01 1"/>
          <exclude name="no_shoulder" body1="base" body2="link1"/>
          <exclude body1="link1" body2="link3"/>
        </contact>""",
    },
    "materials-and-textures": {
        "asset": """<texture name="fade" type="2d" builtin="gradient" width="32" height="32" rgb1="1 1 1" rgb2="0 0 0"/>
          <texture name="sky" type="skybox" builtin="gradient" width="16" height="16" rgb1=".3 .5 .7" rgb2="0 0 0"/>
          <texture name="cube_tex" type="cube" builtin="flat" width="8" height="8" rgb1=".5 .5 .5" mark="edge"
                   markrgb="1 1 1"/>
          <material name="fade_mat" texture="fade" texrepeat="2 2" texuniform="true" emission="0.1" shininess="0.6"/>
          <material name="cube_mat" texture="cube_tex" reflectance="0.2"/>""",
        "link2": '<geom name="link2_vis" type="capsule" fromto="0 0 0 0.3 0 0" size="0.026" group="1" '
        'contype="0" conaffinity="0" material="fade_mat"/>'
        '<site name="painted" material="cube_mat" size="0.01"/>',
        "tip": '<geom name="tip_vis" type="box" size="0.031 0.021 0.021" group="1" contype="0" conaffinity="0"'
        ' material="cube_mat"/>',
    },
    "meshes": {
        "asset": """<mesh name="wedge" vertex="0 0 0  0.05 0 0  0 0.05 0  0 0 0.05"/>
          <mesh name="cube_file" file="cube.obj" scale="1 2 1"/>
          <mesh name="cube_shell" file="cube.obj" inertia="shell" refpos="0.01 0 0"/>""",
        "link1": '<geom name="wedge_col" type="mesh" mesh="wedge" mass="0.05"/>'
        '<geom name="file_vis" type="mesh" mesh="cube_file" group="1" contype="0" conaffinity="0"/>',
        "tip": '<geom name="shell_col" type="mesh" mesh="cube_shell" pos="0.05 0 0" density="200"/>'
        '<geom name="fitted" type="box" mesh="cube_file" group="1" contype="0" conaffinity="0"/>',
    },
    "height-field-on-the-root": {
        "asset": '<hfield name="pad" nrow="3" ncol="3" size="0.05 0.05 0.01 0.005" '
        'elevation="0 1 0 1 2 1 0 1 0"/>',
        "base": '<geom name="pad_col" type="hfield" hfield="pad" pos="0 0 -0.06"/>',
    },
    "ball-and-slide-joints": {
        "tip": BALL_TIP + FINGERS,
        "joint1_attr": 'stiffness="5" springref="0.3" ref="0.1" armature="0.05" damping="0.7"'
        ' frictionloss="0.2" margin="0.01" solreflimit="0.03 1" actuatorfrcrange="-40 40"',
    },
    "floating-root": {
        "base": '<freejoint name="float"/>',
        "sections": '<actuator><motor name="m1" joint="joint1"/></actuator>',
    },
    "degrees-and-orientations": {
        "head": '<compiler angle="degree" eulerseq="zyx" autolimits="true"/>',
        "link1": '<body name="angled" pos="0 0.05 0" euler="30 10 0"><joint name="hinge_deg" range="-90 45"/>'
        '<geom name="angled_col" type="box" size="0.01 0.01 0.01" axisangle="0 0 1 45" mass="0.01"/>'
        '<site name="zsite" zaxis="0 1 1"/></body>',
        "tip": '<geom name="xy" type="capsule" size="0.01 0.02" xyaxes="0 1 0 -1 0 0" mass="0.01"/>',
    },
    "model-wide-sections": {
        "head": """<option timestep="0.004" integrator="implicitfast" gravity="0 0 -9.7" cone="elliptic"
                  jacobian="sparse" impratio="5" noslip_iterations="2"><flag warmstart="disable"/></option>
          <size memory="2M" nuser_jnt="1" nuser_geom="2"/>
          <visual><global offwidth="800" offheight="600"/><quality shadowsize="1024"/>
            <map znear="0.02"/><rgba haze=".1 .2 .3 1"/></visual>
          <statistic meansize="0.1" extent="2" center="0 0 0.5"/>""",
        "joint1_attr": 'user="7"',
        "tip": '<geom name="tagged" size="0.01" pos="0.04 0 0" user="1 2" mass="0.01"/>',
    },
    "explicit-inertials-and-gravcomp": {
        "link1_attr": 'gravcomp="1"',
        "joint1_attr": 'actuatorgravcomp="true"',
        "link1": '<inertial pos="0.15 0 0" mass="1.2" fullinertia="0.01 0.02 0.02 0.001 0 0"/>',
        "link2": '<inertial pos="0.1 0 0" quat="1 0 0 0" mass="0.7" diaginertia="0.004 0.005 0.006"/>',
        "sections": '<actuator><motor name="m1" joint="joint1"/></actuator>',
    },
    "geom-types-and-contact-parameters": {
        "tip": """<geom name="ball" type="sphere" size="0.01" pos="0.05 0 0" contype="2" conaffinity="3" condim="1"/>
          <geom name="egg" type="ellipsoid" size="0.01 0.02 0.015" pos="0.05 0.03 0" priority="2" margin="0.002" gap="0.001"/>
          <geom name="can" type="cylinder" size="0.01 0.02" pos="0.05 -0.03 0" density="500" solmix="0.5"/>
          <geom name="rod" type="capsule" fromto="0 0 0 0 0 0.05" size="0.005" friction="0.5 0.02 0.002"
                solimp="0.9 0.95 0.001 0.5 2" shellinertia="true"/>""",
    },
    "custom-data": {
        "sections": """<custom>
          <numeric name="gains" data="1 2 3"/><numeric name="sized" size="4" data="1"/>
          <text name="note" data="made by hand"/>
          <tuple name="chain"><element objtype="body" objname="link1" prm="0.5"/>
            <element objtype="joint" objname="joint2" prm="1"/><element objtype="site" objname="tip"/></tuple>
        </custom>""",
    },
    "keyframes-in-the-file": {
        "sections": """<actuator><position name="p1" joint="joint1" kp="10"/></actuator>
        <keyframe><key name="ready" qpos="0.3 -0.2 0.1" ctrl="0.3"/><key name="zero"/></keyframe>""",
    },
    "site-types": {
        "tip": '<site name="box_site" type="box" size="0.01 0.01 0.01" group="4"/>'
        '<site name="cap_site" type="capsule" fromto="0 0 0 0.02 0 0" size="0.005"/>'
        '<site name="cyl_site" type="cylinder" size="0.01 0.005" rgba="0 0 1 0.5"/>'
        '<site name="ell_site" type="ellipsoid" size="0.01 0.02 0.005"/>',
    },
    "skin": {
        "asset": """<skin name="sleeve" vertex="0 0 0  0.3 0 0  0 0.3 0" face="0 1 2" rgba=".5 .5 1 1">
            <bone body="link1" bindpos="0 0 -0.2" bindquat="1 0 0 0" vertid="0 1" vertweight="1 1"/>
            <bone body="link2" bindpos="-0.3 0 -0.2" bindquat="1 0 0 0" vertid="2" vertweight="1"/>
          </skin>""",
    },
    "skin-from-a-file": {
        "asset": '<skin name="sleeve_file" file="sleeve.skn" inflate="0.01"/>',
    },
    "gripper-like-coupled-fingers": {
        "tip": FINGERS,
        "sections": """<tendon><fixed name="split"><joint joint="finger_left_slide" coef="0.5"/>
            <joint joint="finger_right_slide" coef="0.5"/></fixed></tendon>
        <equality><joint joint1="finger_left_slide" joint2="finger_right_slide"/></equality>
        <actuator><general name="fingers" tendon="split" ctrlrange="0 255" forcerange="-5 5"
            gainprm="0.1568" biasprm="0 -100 -10" biastype="affine"/></actuator>
        <sensor><tendonpos name="opening" tendon="split"/></sensor>""",
    },
    "world-level-elements": {
        "world": '<geom name="floor_marker" type="box" size="0.1 0.1 0.001" pos="1 0 0" group="1" contype="0"'
        ' conaffinity="0"/><site name="target" pos="0.5 0.5 0.5"/>'
        '<camera name="side" pos="0 -2 1" xyaxes="1 0 0 0 0.4 1"/>',
    },
}
"""Each case: the slots of :data:`ARM` it fills (the others stay empty)."""


def robot_mjcf(name: str) -> str:
    """The MJCF text of case ``name``."""
    filled = {slot: CASES[name].get(slot, "") for slot in SLOTS}
    return ARM.format(name=name, **filled)
