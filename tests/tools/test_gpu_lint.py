"""``assembler lint --target mjwarp`` and ``--target mjx`` against the real engines on CPU.

Each rule has a small robot that breaks it: the engine's own ``put_model`` refuses it (or, for the
constraint budget and mesh sizes, runs it badly), and the lint finds it; a clean robot passes both.
The engines are optional: a test skips, saying how to install one, where it is absent (CI runs
these where the engines are installed: .ci/run adds the warp and mjx extras to its newest-MuJoCo environment).
"""

from __future__ import annotations

import importlib.util
import json
import math
import re
import warnings
from collections.abc import Callable
from pathlib import Path
from types import ModuleType
from typing import Any

import mujoco
import numpy as np
import pytest

from assembler.cli import main
from assembler.cli.arguments import LINT_TARGETS
from assembler.gpu.mjx_checks import MJX_COLLISION_PAIRS, MJX_ELEMENT_KINDS, MJX_ENABLE_REFUSED
from assembler.gpu.warp_checks import (
    WARP_DISABLE_REFUSED,
    WARP_ELEMENT_KINDS,
    WARP_ENABLE_REFUSED,
    WARP_SOLVERS_REFUSED,
    warp_default_njmax,
)
from assembler.registry.catalog import classes_named
from assembler.registry.instances import assemble
from assembler.tools.lint import ENGINES

Write = Callable[[str, str], Path]

ROBOT_MJCF = """\
<mujoco model="gpuprobe">
  <compiler angle="radian" autolimits="true"/>
  {option}
  {extension}
  <asset>{asset}</asset>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="{base_type}" {base_shape} mass="2" {base_extra}/>
      <body name="link1" pos="0 0 0.15">
        <joint name="shoulder" axis="0 0 1" range="-2 2"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0 0 0.3" size="0.03" mass="1"/>
        <body name="link2" pos="0 0 0.3">
          <joint name="elbow" axis="0 1 0" range="-2 2"/>
          <geom name="link2_col" type="{tip_type}" size="0.04 0.04 0.04" pos="0 0 0.1" mass="0.5"/>
          <body name="right_hand" pos="0 0 0.2"/>
        </body>
      </body>
    </body>
  </worldbody>
  <actuator>
    <position name="act_shoulder" joint="shoulder" kp="200" dampratio="1" ctrlrange="-2 2" forcerange="-80 80"/>
    <position name="act_elbow" joint="elbow" kp="100" dampratio="1" ctrlrange="-2 2" forcerange="-40 40"/>
    {actuators}
  </actuator>
  {tail}
</mujoco>
"""
"""A two-link arm on a base welded to the world: the base's geom and link 2's can collide (MuJoCo
filters parent and child, never a pair across a link), so their types decide what MJX can do."""

CLEAN: dict[str, str] = {
    "option": "",
    "extension": "",
    "asset": "",
    "base_type": "box",
    "base_shape": 'size="0.05 0.05 0.05"',
    "base_extra": "",
    "tip_type": "capsule",
    "actuators": "",
    "tail": "",
}
"""Box against capsule (MJX has it), Newton solver, position servos: both engines accept it."""

CUBE = "-1 -1 -1  1 -1 -1  -1 1 -1  1 1 -1  -1 -1 1  1 -1 1  -1 1 1  1 1 1"


def sphere_points(count: int, radius: float = 0.06) -> str:
    """``count`` points spread over a sphere (a Fibonacci lattice): a convex hull with that many vertices."""
    golden = math.pi * (3 - math.sqrt(5))
    points = []
    for i in range(count):
        z = 1 - 2 * (i + 0.5) / count
        r, angle = math.sqrt(1 - z * z), golden * i
        points.append(
            f"{radius * r * math.cos(angle):.5f} {radius * r * math.sin(angle):.5f} {radius * z:.5f}"
        )
    return "  ".join(points)


def robot(write: Write, name: str = "GpuProbe", **changes: str) -> Path:
    """The probe robot with ``changes`` to its template, written as a spec folder; the spec file."""
    write(f"{name}/probe.xml", ROBOT_MJCF.format(**{**CLEAN, **changes}))
    return write(f"{name}/probe.yaml", f"name: {name}\nmjcf: probe.xml\ninit_qpos: [0.3, -0.5]\n")


def compiled(spec: Path) -> mujoco.MjModel:
    """The assembled robot's compiled model, as ``assembler lint`` and ``assembler build`` see it."""
    (cls,) = classes_named([str(spec)])
    return assemble(cls.__name__).get_model(cache=False)


def gpu_findings(capsys: pytest.CaptureFixture[str], spec: Path, target: str) -> list[dict[str, Any]]:
    """The findings of ``assembler lint SPEC --target TARGET`` that only that target reports."""
    capsys.readouterr()  # what came before (an engine's start-up lines) is not the report
    main(["lint", str(spec), "--target", target, "--format", "json"])
    report = json.loads(capsys.readouterr().out)
    assert report["problems"] == []
    return [f for t in report["targets"] for f in t["findings"] if f["code"].startswith("RA8")]


def codes(findings: list[dict[str, Any]]) -> list[tuple[str, str, str]]:
    return [(f["code"], f["severity"], f["subject"]) for f in findings]


@pytest.fixture(scope="module")
def warp() -> ModuleType:
    engine = pytest.importorskip(
        "mujoco_warp", reason="MuJoCo Warp is not installed (pip install mujoco-warp; CI: .ci/run)"
    )
    pytest.importorskip("warp").config.quiet = True  # its start-up banner would mix with lint's output
    return engine


@pytest.fixture(scope="module")
def mjx() -> ModuleType:
    return pytest.importorskip(
        "mujoco.mjx", reason="MJX is not installed (pip install -e '.[mjx]'; CI: .ci/run)"
    )


def test_the_lint_targets_on_the_command_line_are_the_engines_lint_knows() -> None:
    assert LINT_TARGETS == ENGINES


# ----- a clean robot ----------------------------------------------------------------------------


def test_a_clean_robot_passes_mujoco_warps_put_model_and_lint_only_says_its_contact_room(
    capsys: pytest.CaptureFixture[str], write: Write, warp: ModuleType
) -> None:
    spec = robot(write)
    warp.put_model(compiled(spec))
    findings = gpu_findings(capsys, spec, "mjwarp")
    assert codes(findings) == [("RA803", "info", "GpuProbe")]
    assert "leaves room for 15 contacts per world" in findings[0]["why"]


def test_a_clean_robot_passes_mjxs_put_model_and_has_no_mjx_findings(
    capsys: pytest.CaptureFixture[str], write: Write, mjx: ModuleType
) -> None:
    spec = robot(write)
    mjx.put_model(compiled(spec))
    assert gpu_findings(capsys, spec, "mjx") == []


# ----- MuJoCo Warp ------------------------------------------------------------------------------

WARP_REFUSALS = {
    "pgs_solver": ({"option": '<option solver="PGS"/>'}, "RA801", "option", "mjSOL_PGS is unsupported"),
    "midphase_disabled": (
        {"option": '<option><flag midphase="disable"/></option>'},
        "RA801",
        "option",
        "mjDSBL_MIDPHASE is unsupported",
    ),
    "override_enabled": (
        {"option": '<option><flag override="enable"/></option>'},
        "RA801",
        "option",
        "mjENBL_OVERRIDE is unsupported",
    ),
    "pid_plugin": (
        {
            "extension": '<extension><plugin plugin="mujoco.pid"/></extension>',
            "actuators": '<plugin name="pid" plugin="mujoco.pid" joint="shoulder"/>',
        },
        "RA802",
        "robot0_pid",
        "Actuator plugins not supported",
    ),
}


def chain_mjcf(joints: int) -> str:
    """A chain of ``joints`` hinges, each with friction loss: one constraint row each, always active."""
    opening = "".join(
        f'<body name="l{i}" pos="0 0 0.01"><joint name="j{i}" axis="0 1 0" range="-1 1" frictionloss="0.1"/>'
        f'<geom name="g{i}" type="capsule" size="0.005 0.004" mass="0.01" contype="0" conaffinity="0"/>'
        for i in range(joints)
    )
    return (
        '<mujoco model="chain"><worldbody><body name="base"><geom type="sphere" size="0.01" mass="1"/>'
        f'{opening}<body name="right_hand"/>{"</body>" * joints}</body></worldbody></mujoco>'
    )


def test_more_constraint_rows_than_warps_default_njmax_is_a_warning_and_warp_drops_them(
    capsys: pytest.CaptureFixture[str], write: Write, warp: ModuleType
) -> None:
    write("chain/chain.xml", chain_mjcf(70))
    spec = write("chain/chain.yaml", "name: Chain\nmjcf: chain.xml\n")
    model = compiled(spec)
    cpu = mujoco.MjData(model)
    mujoco.mj_forward(model, cpu)
    njmax = warp_default_njmax(model)
    assert cpu.nefc == 70 > njmax == 64
    # what MuJoCo Warp does with its default sizes: the rows past njmax are dropped, the world flagged
    gpu_model, gpu_data = warp.put_model(model), warp.make_data(model)
    warp.step(gpu_model, gpu_data)
    assert int(gpu_data.overflow.numpy()[0]) & int(warp.OverflowType.NEFC)
    (finding,) = gpu_findings(capsys, spec, "mjwarp")
    assert (finding["code"], finding["severity"]) == ("RA803", "warning")
    assert finding["why"].startswith(
        "up to 140 constraint rows before any contact (70 friction loss, 70 limit)"
    )
    assert "pass njmax=172" in finding["fix"]
    # with the njmax the lint advises, no row is dropped
    sized = warp.make_data(model, njmax=172)
    warp.step(gpu_model, sized)
    assert not int(sized.overflow.numpy()[0])


def test_the_refusal_tables_are_mujoco_warps_own(warp: ModuleType) -> None:
    types = pytest.importorskip("mujoco_warp._src.types")
    supported = {
        "mjtTrn": types.TrnType,
        "mjtDyn": types.DynType,
        "mjtGain": types.GainType,
        "mjtBias": types.BiasType,
        "mjtEq": types.EqType,
        "mjtSensor": types.SensorType,
    }
    placeholders = {"mjTRN_UNDEFINED"}
    for table in WARP_ELEMENT_KINDS:
        enum = getattr(mujoco, table.enum)
        have = {int(v) for v in supported[table.enum]}
        missing = {n for n, v in enum.__members__.items() if int(v) not in have} - placeholders
        assert set(table.refused) == missing, table.field
    assert {
        m.name for m in mujoco.mjtSolver.__members__.values() if int(m) not in set(types.SolverType)
    } == set(WARP_SOLVERS_REFUSED)
    for enum, ours in (("mjtEnableBit", WARP_ENABLE_REFUSED), ("mjtDisableBit", WARP_DISABLE_REFUSED)):
        bits = int(np.bitwise_or.reduce([int(b) for b in getattr(types, enum[3:])]))
        members = getattr(mujoco, enum).__members__.items()
        assert {n for n, v in members if int(v) & ~bits and not n.startswith("mjN")} == set(ours)


# ----- MJX --------------------------------------------------------------------------------------

MESH_ASSET = f'<mesh name="hull" vertex="{CUBE}" scale="0.04 0.04 0.04"/>'
MESH_BASE = {"asset": MESH_ASSET, "base_type": "mesh", "base_shape": 'mesh="hull"'}

MJX_REFUSALS = {
    "box_cylinder": (
        {"tip_type": "cylinder"},
        "RA811",
        "robot0_link2_col",
        "(mjtGeom.mjGEOM_CYLINDER, mjtGeom.mjGEOM_BOX) collisions not implemented",
    ),
    "box_ellipsoid": (
        {"tip_type": "ellipsoid"},
        "RA811",
        "robot0_link2_col",
        "(mjtGeom.mjGEOM_ELLIPSOID, mjtGeom.mjGEOM_BOX) collisions not implemented",
    ),
    "cylinder_mesh": (
        {**MESH_BASE, "tip_type": "cylinder"},
        "RA811",
        "robot0_link2_col",
        "(mjtGeom.mjGEOM_CYLINDER, mjtGeom.mjGEOM_MESH) collisions not implemented",
    ),
    "ellipsoid_mesh": (
        {**MESH_BASE, "tip_type": "ellipsoid"},
        "RA811",
        "robot0_link2_col",
        "(mjtGeom.mjGEOM_ELLIPSOID, mjtGeom.mjGEOM_MESH) collisions not implemented",
    ),
    "implicit_integrator": (
        {"option": '<option integrator="implicit"/>'},
        "RA812",
        "option",
        "mjINT_IMPLICIT",
    ),
    "pgs_solver": ({"option": '<option solver="PGS"/>'}, "RA812", "option", "mjSOL_PGS"),
    "energy_enabled": (
        {"option": '<option><flag energy="enable"/></option>'},
        "RA812",
        "option",
        "mjENBL_ENERGY",
    ),
    "adhesion_actuator": (
        {"actuators": '<adhesion name="sticky" body="link2" ctrlrange="0 1"/>'},
        "RA813",
        "robot0_sticky",
        "mjTRN_BODY",
    ),
    "joint_limit_sensor": (
        {"tail": '<sensor><jointlimitpos name="limit" joint="elbow"/></sensor>'},
        "RA813",
        "robot0_limit",
        "mjSENS_JOINTLIMITPOS",
    ),
    "mesh_margin": (
        {**MESH_BASE, "base_extra": 'margin="0.01"'},
        "RA814",
        "robot0_link1_col / robot0_base_col",
        "margin/gap not implemented",
    ),
}


ENGINE_REFUSALS = [("mjwarp", case) for case in sorted(WARP_REFUSALS)] + [
    ("mjx", case) for case in sorted(MJX_REFUSALS)
]
"""(lint target, case) for every refusal of either engine's ``put_model``."""


@pytest.mark.parametrize(("target", "case"), ENGINE_REFUSALS)
def test_what_an_engine_refuses_is_a_lint_error_naming_the_element(
    target: str, case: str, capsys: pytest.CaptureFixture[str], write: Write, request: pytest.FixtureRequest
) -> None:
    engine: ModuleType = request.getfixturevalue("warp" if target == "mjwarp" else "mjx")
    changes, code, subject, refusal = (WARP_REFUSALS if target == "mjwarp" else MJX_REFUSALS)[case]
    spec = robot(write, **changes)
    with pytest.raises(NotImplementedError, match=re.escape(refusal)):
        engine.put_model(compiled(spec))
    findings = [f for f in gpu_findings(capsys, spec, target) if f["severity"] == "error"]
    assert codes(findings)[0] == (code, "error", subject)
    assert {f["code"] for f in findings} == {code}  # a margin on the base's mesh: both links' pairs
    assert "put_model refuses" in findings[0]["why"] and findings[0]["fix"]


def test_a_cylinder_that_cannot_touch_the_box_is_not_reported_and_mjx_accepts_it(
    capsys: pytest.CaptureFixture[str], write: Write, mjx: ModuleType
) -> None:
    # contype/conaffinity without a common bit: the pair never reaches a collision function
    spec = robot(write, tip_type='cylinder" contype="2" conaffinity="2')
    mjx.put_model(compiled(spec))
    assert gpu_findings(capsys, spec, "mjx") == []


def test_a_box_cylinder_finding_says_which_geom_to_change_and_where(
    capsys: pytest.CaptureFixture[str], write: Write
) -> None:
    spec = robot(write, tip_type="cylinder")
    (finding,) = gpu_findings(capsys, spec, "mjx")
    assert finding["why"] == (
        "cylinder of body robot0_link2 can collide with 1 box geom(s) (robot0_base_col), and MJX has no "
        "cylinder-box collision: its put_model refuses the model"
    )
    assert finding["fix"].startswith(
        "make robot0_link2_col a capsule of the same size, or keep the pairs apart"
    )
    assert (Path(finding["file"]).name, finding["line"]) == ("probe.xml", 14)


def test_a_mesh_hull_too_large_for_mjx_is_a_warning_and_mjx_keeps_every_vertex(
    capsys: pytest.CaptureFixture[str], write: Write, mjx: ModuleType
) -> None:
    big = f'<mesh name="hull" vertex="{sphere_points(300)}"/>'
    spec = robot(write, **{**MESH_BASE, "asset": big})
    model = compiled(spec)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # MJX's own warnings about coplanar faces, if any
        device_model = mjx.put_model(model)
    # what MJX's separating-axis test will run over, every step, in every world
    assert device_model._impl.mesh_convex[0].vert.shape[0] == 300
    (finding,) = gpu_findings(capsys, spec, "mjx")
    assert codes([finding]) == [("RA815", "warning", "robot0_base_col")]
    assert "convex hull has 300 vertices and collides with primitives" in finding["why"]
    assert finding["fix"].startswith('add maxhullvert="64" to <mesh name="hull">')
    # the fix: MuJoCo's compiler keeps 64 hull vertices, MJX gets those, the warning goes
    fixed = robot(write, "GpuProbeFixed", **{**MESH_BASE, "asset": big.replace("/>", ' maxhullvert="64"/>')})
    assert mjx.put_model(compiled(fixed))._impl.mesh_convex[0].vert.shape[0] <= 64
    assert gpu_findings(capsys, fixed, "mjx") == []


def test_the_refusal_tables_are_mjxs_own(mjx: ModuleType) -> None:
    types = pytest.importorskip("mujoco.mjx._src.types")
    driver = pytest.importorskip("mujoco.mjx._src.collision_driver")
    pairs = {(types.GeomType(a).name, types.GeomType(b).name) for a, b in driver._COLLISION_FUNC}
    assert pairs == set(MJX_COLLISION_PAIRS)
    supported = {
        "mjtTrn": types.TrnType,
        "mjtDyn": types.DynType,
        "mjtGain": types.GainType,
        "mjtBias": types.BiasType,
        "mjtEq": types.EqType,
        "mjtSensor": types.SensorType,
    }
    placeholders = {"mjTRN_UNDEFINED"}
    for table in MJX_ELEMENT_KINDS:
        enum = getattr(mujoco, table.enum)
        have = {int(v) for v in supported[table.enum]}
        missing = {n for n, v in enum.__members__.items() if int(v) not in have} - placeholders
        assert set(table.refused) == missing, table.field
    have = {int(v) for v in types.EnableBit}
    members = mujoco.mjtEnableBit.__members__.items()
    assert {n for n, v in members if int(v) not in have and not n.startswith("mjN")} == set(
        MJX_ENABLE_REFUSED
    )


# ----- assembler build --target mjwarp ----------------------------------------------------------


def test_build_for_mujoco_warp_hands_the_model_to_its_put_model_and_writes_it(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path, warp: ModuleType
) -> None:
    out = tmp_path / "probe_out.xml"
    assert main(["build", str(robot(write)), "--target", "mjwarp", "-o", str(out)]) == 0
    assert "GpuProbe: MuJoCo Warp 4.0.0 accepted the model (put_model)" in capsys.readouterr().err
    assert mujoco.MjModel.from_xml_path(str(out)).nu == 2


def test_build_for_mujoco_warp_of_a_model_it_refuses_fails_in_one_line_and_writes_nothing(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path, warp: ModuleType
) -> None:
    out = tmp_path / "probe_out.xml"
    spec = robot(write, option='<option solver="PGS"/>')
    assert main(["build", str(spec), "--target", "mjwarp", "-o", str(out)]) == 1
    assert capsys.readouterr().err.splitlines()[-1] == (
        "GpuProbe: MuJoCo Warp's put_model refuses the model: mjSOL_PGS is unsupported. (assembler lint "
        "GpuProbe --target mjwarp names the element and the fix)"
    )
    assert not out.exists()


def test_build_for_mujoco_warp_without_it_installed_says_so_and_writes_the_model(
    capsys: pytest.CaptureFixture[str], write: Write, tmp_path: Path
) -> None:
    if importlib.util.find_spec("mujoco_warp") is not None:
        pytest.skip("MuJoCo Warp is installed here: the two tests above cover it")
    out = tmp_path / "probe_out.xml"
    assert main(["build", str(robot(write)), "--target", "mjwarp", "-o", str(out)]) == 0
    assert capsys.readouterr().err.splitlines()[0] == (
        "GpuProbe: MuJoCo Warp is not installed, so its put_model did not run (pip install mujoco-warp); "
        "assembler lint GpuProbe --target mjwarp checks the model without it"
    )
    assert out.exists()
