"""Published robots, each given a spec by ``assembler new`` and nothing else: it validates and builds,
equals MuJoCo's own load of the vendor's file, renders, and (arms) runs 200 steps of robosuite's Lift.

A case blocked by a known defect of issue 24 is a strict xfail naming it: it fails once the defect
is fixed, so the mark is removed with the fix. The conventions our build applies on purpose, and
which the comparison leaves out, are listed in :data:`CONVENTIONS`.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

import mujoco
import numpy as np
import pytest
import yaml

import assembler
from assembler.errors import AssemblerError
from assembler.models import RobotModel
from assembler.tools.render.picture import render_views
from assembler.tools.render.stage import build_stage
from tests.corpus.cases import CASES, Case
from tests.corpus.conftest import Corpus
from tests.corpus.direct_load import direct_load, reads_collada
from tests.tools.test_render import robot_mask

pytestmark = pytest.mark.corpus

CONVENTIONS = {
    "names": "every element of ours carries the part's prefix (robot0_, gripper0_)",
    "collision colour": "group-0 (collision) geoms keep the file's colour in the specs new writes "
    "(collision_colour: file) and are drawn in robosuite's green inside robosuite; their colour is not compared",
    "task scenes": "a task scene is compared as the robot alone: MuJoCo's load of the file with the scene "
    "deleted through MjSpec (direct_load.robot_alone), not through the spec's mjcf_fixes",
    "size": "MuJoCo's attach keeps the assembly's memory sizes and warns (the Shadow hand's njmax, nconmax)",
    "URDF visual geoms": "a URDF's <visual> geoms are kept in group 1 without contacts, as robosuite "
    "expects; MuJoCo's import puts them in group 0 with contacts: their group is not compared",
    "actuators": "the motors `assembler new` adds to a file without actuators are not in the vendor's file",
    "stand-in load": "a mobile base built alone carries a 1 kg body on its support, where a robot goes",
}
"""Where our build differs from MuJoCo's direct load on purpose (docs/add-your-robot.md lists them)."""


CONTINUOUS_LIMITS = (
    "MuJoCo 3.9's URDF import limits a continuous joint that has a <limit lower upper> (racecar's right "
    "steering hinge, R2-D2's head swivel); MuJoCo 4.0 and our read leave it unlimited, as the URDF "
    "format says a continuous joint is"
)

MESH_STEMS = (
    "MuJoCo 3.9's URDF import names a mesh after its file's stem and gives a later <mesh filename> of a stem "
    "already taken the first file's mesh, whatever its folder (xml_urdf.cc, mjXURDF::Geom: same name and "
    "scale, one mesh); MuJoCo 4.0's import loads it as a mesh of its own (<stem>1), and our read hands MuJoCo "
    "such a file as a copy of its own name on every version (assembler/urdf/mesh_formats.py)"
)

ON_MUJOCO_3_9 = {
    "talos": f"{MESH_STEMS}: on MuJoCo 3.9 the geoms of gripper_left_base_link and gripper_right_base_link "
    "(meshes/gripper/base_link.STL, base_link_collision.STL) take the torso's meshes/torso/base_link.STL and "
    "base_link_collision.STL, up to 0.164 m larger",
    "panda_pybullet": "MuJoCo 3.9's URDF import ignores <mimic> (panda_finger_joint2's <mimic "
    'joint="panda_finger_joint1"/>), so its load has no equality; MuJoCo 4.0\'s import and our read '
    "(assembler/urdf/postprocess.py add_mimics, on every version) make it the joint equality "
    "panda_finger_joint2 = 0 + 1 * panda_finger_joint1 (polycoef 0 1 0 0 0), as the URDF format says. And "
    f"{MESH_STEMS}: on MuJoCo 3.9 the collision geoms of panda_link1-6, panda_hand and the fingers "
    "(meshes/collision/link1.obj, ...) take the visual meshes (meshes/visual/link1.obj, ...)",
    "racecar": CONTINUOUS_LIMITS,
    "r2d2": CONTINUOUS_LIMITS,
}
"""Measured differences from MuJoCo's direct load on MuJoCo 3.9 only (CI runs the corpus there, its
extra caps MuJoCo below 4): strict, so a fix shows."""


def _cases(stage: str, arms_only: bool = False, robots_only: bool = False) -> list[Any]:
    params = []
    for case in CASES:
        if (arms_only and not case.arm) or (robots_only and not case.robot) or case.refused:
            continue
        defect = case.blocked(stage)
        error: type[Exception] = ValueError if stage in case.tracebacks else AssemblerError
        if stage in case.defects and stage in ("jaw", "hold"):  # the build works; the check finds the defect
            error = AssertionError
        marks = [pytest.mark.xfail(reason=defect, raises=error, strict=True)] if defect else []
        if stage == "compare" and case.id in ON_MUJOCO_3_9 and mujoco.__version__.startswith("3.9."):
            marks.append(pytest.mark.xfail(reason=ON_MUJOCO_3_9[case.id], raises=AssertionError, strict=True))
        marks += [pytest.mark.filterwarnings(f"ignore:{message}") for message in case.warnings]
        params.append(pytest.param(case, id=case.id, marks=marks))
    return params


def _part(case: Case, corpus: Corpus) -> Any:
    """The case's part as ``new`` wrote it; an arm whose jaws ``new`` cut from the file with those jaws
    as its grippers (together they are the vendor's file), every other robot alone."""
    name = corpus.name(case)
    if case.id in corpus.jaws:
        return assembler.assemble(name, base=None)
    if case.robot:
        return assembler.create_robot(name, idn=0)
    if case.kind == "base":
        return assembler.create_base(name, idn=0)
    return assembler.create_gripper(name, idn=0)


def _compiled(part: Any) -> mujoco.MjModel:
    return part.get_model() if isinstance(part, RobotModel) else part.compile_alone()


@pytest.mark.parametrize("case", [pytest.param(c, id=c.id) for c in CASES if c.refused])
def test_new_refuses_a_file_mujoco_refuses_in_one_line_naming_its_fault(case: Case, corpus: Corpus) -> None:
    with pytest.raises(AssemblerError) as refused:
        corpus.spec(case)
    (line,) = str(refused.value).splitlines()
    assert case.refused in line and str(corpus.model_file(case).name) in line


@pytest.mark.parametrize("case", _cases("build"))
def test_new_writes_a_spec_that_validates_and_builds_as_written(case: Case, corpus: Corpus) -> None:
    part = _part(case, corpus)
    model = _compiled(part)
    assert model.njnt > 0 and model.nbody > 2
    assert part.spec.source_file == f"package://{case.package}/{case.file}"  # the installed file, not a copy


@pytest.mark.parametrize("case", [p for p in _cases("hold", arms_only=True)])
def test_a_fixed_base_arm_holds_its_home_pose_for_a_second_with_ctrl_at_home(
    case: Case, corpus: Corpus
) -> None:
    robot = _part(case, corpus)
    if not robot.spec.actuators:
        pytest.skip("the file's own actuators drive the arm (new adds servos only to a file without any)")
    model = robot.get_model()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    home = data.qpos.copy()
    data.ctrl[:] = home[model.jnt_qposadr[model.actuator_trnid[:, 0]]]
    worst = 0.0
    for _ in range(round(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
        worst = max(worst, float(np.max(np.abs(data.qpos - home))))
    assert worst < 0.1


@pytest.mark.parametrize("case", [p for p in _cases("hold") if p.values[0].kind == "base"])
def test_a_mobile_base_turns_its_wheels_at_the_commanded_speed_and_holds_the_rest(
    case: Case, corpus: Corpus
) -> None:
    base = assembler.create_base(corpus.name(case), idn=0)
    model = base.compile_alone()
    data = mujoco.MjData(model)
    mujoco.mj_resetDataKeyframe(model, data, 0)
    home = data.qpos.copy()
    joints = model.actuator_trnid[:, 0]
    spinning = model.actuator_biastype == mujoco.mjtBias.mjBIAS_AFFINE  # velocity and position servos
    spinning &= model.actuator_biasprm[:, 1] == 0  # velocity servos have no position term
    assert spinning.any(), "no wheel got a velocity servo"
    data.ctrl[:] = np.where(spinning, 2.0, home[model.jnt_qposadr[joints]])  # 2 rad/s; the rest at home
    for _ in range(round(1.0 / model.opt.timestep)):
        mujoco.mj_step(model, data)
    speeds = data.qvel[model.jnt_dofadr[joints[spinning]]]
    held = model.jnt_qposadr[joints[~spinning]]
    np.testing.assert_allclose(speeds, 2.0, rtol=0.02)
    assert np.all(np.abs(data.qpos[held] - home[held]) < 0.1)


JAWS = (
    "so101",
    "so101_urdf",
    "fetch",
    "metaworld_sawyer",
    "aloha_viperx",
    "panda_erd",
    "panda_pybullet",
    "baxter",
)
"""Arms whose file holds their own jaw (Baxter: one on each arm)."""

TWO_HANDS = ("baxter",)
"""Bimanual robots whose file holds a hand on each arm, each cut into a gripper of its own."""


@pytest.mark.parametrize("case", [p for p in _cases("jaw") if p.values[0].id in JAWS])
def test_a_jaw_in_the_arms_file_is_the_robots_gripper_or_left_out_of_the_arm(
    case: Case, corpus: Corpus
) -> None:
    robot = _part(case, corpus)
    model = robot.get_model()
    if not any(robot.spec.default_grippers.values()):  # its hand turns on an arm joint (SO-101's wrist
        # roll): the jaw stays, out of the arm, below its end effector
        for arm in robot.arms:
            hand = robot.eef_name[arm]
            below = {
                j
                for j in robot.joints
                if hand in _ancestors(model, model.body_parentid[model.joint(j).bodyid[0]])
            }
            assert below and not below & set(robot.arm_joints)
        return
    grippers = [robot.grippers[arm] for arm in robot.arms]  # each arm's own hand (Baxter's two)
    assert robot.spec.remove_bodies == [g.spec.root_body for g in grippers]  # cut, made the grippers
    for gripper in grippers:
        assert gripper.dof >= 1  # an action that opens and closes it
        jaw_joints = [
            model.joint(j).name
            for j in range(model.njnt)
            if model.joint(j).name.startswith(gripper.naming_prefix)
        ]
        assert jaw_joints and not set(robot.arm_joints) & set(jaw_joints)


def _ancestors(model: mujoco.MjModel, body: int) -> list[str]:
    """The names of ``body`` and the bodies above it."""
    names = []
    while body > 0:
        names.append(model.body(body).name)
        body = int(model.body_parentid[body])
    return names


def _pose(model: mujoco.MjModel, root: int) -> tuple[np.ndarray, np.ndarray]:
    """Every body's position and rotation in the root body's frame, at qpos0."""
    data = mujoco.MjData(model)
    mujoco.mj_kinematics(model, data)
    rotation = data.xmat[root].reshape(3, 3)
    positions = (data.xpos - data.xpos[root]) @ rotation
    frames = np.array([rotation.T @ data.xmat[b].reshape(3, 3) for b in range(model.nbody)])
    return positions, frames


def _rgba(model: mujoco.MjModel, geom: int) -> tuple[float, ...]:
    material = model.geom_matid[geom]
    return tuple(np.round(model.mat_rgba[material] if material >= 0 else model.geom_rgba[geom], 6))


def _geoms(model: mujoco.MjModel, body: int, colours: bool) -> np.ndarray:
    """The body's geoms as rows sorted by type and size: type, size, and (non-collision geoms of an
    MJCF) colour, else -1s."""
    rows = []
    for geom in np.flatnonzero(model.geom_bodyid == body):
        shown = colours and model.geom_group[geom] != 0
        rgba = _rgba(model, geom) if shown else (-1.0,) * 4
        rows.append((float(model.geom_type[geom]), *model.geom_size[geom], *rgba))
    return np.array(sorted(rows, key=lambda row: tuple(np.round(row, 3)))).reshape(-1, 8)


@pytest.mark.parametrize("case", _cases("compare"))
def test_the_build_equals_mujocos_direct_load_of_the_vendors_file(case: Case, corpus: Corpus) -> None:
    part = _part(case, corpus)
    ours, prefix = _compiled(part), part.naming_prefix
    scene_cut = any(fix.delete for fix in part.spec.mjcf_fixes)  # the robot of a task scene alone
    root = part.root_body.removeprefix(prefix) if scene_cut else None
    if part.spec.source_field == "urdf" and reads_collada(corpus.model_file(case)):
        pytest.skip("MuJoCo alone reads no COLLADA mesh: there is no direct load to compare with")
    theirs = direct_load(corpus.model_file(case), part.spec.source_field == "urdf", part.spec, root)
    root_name = theirs.body(1).name
    ours_pose, theirs_pose = _pose(ours, ours.body(prefix + root_name).id), _pose(theirs, 1)
    colours = part.spec.source_field == "mjcf"
    counts = ("nbody", "njnt", "ngeom", "nsite", "neq", "ntendon", "nsensor", "nuser_actuator", "nuser_jnt")
    stand_in = int(case.kind == "base")  # the load a base built alone carries (CONVENTIONS)
    assert [getattr(ours, n) for n in counts] == [
        getattr(theirs, n) + (stand_in if n == "nbody" else 0) for n in counts
    ]  # nothing more, nothing less, and every user-data column
    prefixes = (prefix, *(gripper.naming_prefix for gripper in getattr(part, "grippers", {}).values()))

    def mine_of(kind: str, name: str) -> int:
        """Our element of the vendor's ``name``: the robot's, or the jaw's cut from it."""
        for each in prefixes:
            found = mujoco.mj_name2id(ours, getattr(mujoco.mjtObj, f"mjOBJ_{kind}"), each + name)
            if found >= 0:
                return int(found)
        raise AssertionError(f"no {kind.lower()} {name} under {prefixes}")

    for body in range(1, theirs.nbody):
        name = theirs.body(body).name
        mine = mine_of("BODY", name)
        assert ours.body_mass[mine] == pytest.approx(theirs.body_mass[body], rel=1e-6), name
        np.testing.assert_allclose(
            ours.body_inertia[mine], theirs.body_inertia[body], rtol=1e-6, err_msg=name
        )
        np.testing.assert_allclose(ours_pose[0][mine], theirs_pose[0][body], atol=1e-6, err_msg=name)
        np.testing.assert_allclose(ours_pose[1][mine], theirs_pose[1][body], atol=1e-6, err_msg=name)
        np.testing.assert_allclose(
            _geoms(ours, mine, colours), _geoms(theirs, body, colours), atol=1e-5, err_msg=name
        )
    for joint in range(theirs.njnt):
        name = theirs.joint(joint).name
        if not name:  # the free joint a URDF spec adds (add_free_joint), unnamed in both
            assert sum(ours.jnt_type == mujoco.mjtJoint.mjJNT_FREE) == 1
            continue
        mine = mine_of("JOINT", name)
        assert ours.jnt_type[mine] == theirs.jnt_type[joint], name
        assert bool(ours.jnt_limited[mine]) == bool(theirs.jnt_limited[joint]), name
        np.testing.assert_allclose(ours.jnt_range[mine], theirs.jnt_range[joint], atol=1e-9, err_msg=name)
        np.testing.assert_allclose(ours.jnt_axis[mine], theirs.jnt_axis[joint], atol=1e-9, err_msg=name)
        dof, their_dof = ours.jnt_dofadr[mine], theirs.jnt_dofadr[joint]
        for field in ("dof_damping", "dof_armature", "dof_frictionloss"):
            assert getattr(ours, field)[dof] == pytest.approx(getattr(theirs, field)[their_dof]), (
                name,
                field,
            )


@pytest.mark.parametrize("case", _cases("render", robots_only=True))
def test_the_robot_renders_visibly(case: Case, corpus: Corpus) -> None:
    stage = build_stage(assembler.assemble(corpus.name(case)), 160, 120)
    (image,) = render_views(stage, ["iso"], 160, 120)
    assert robot_mask(stage, image, "iso").mean() > 0.02  # the robot covers at least 2% of the picture


# The bridge says what it adds for robosuite (a right_center site, grip frames); expected here.
@pytest.mark.filterwarnings("ignore::assembler.errors.AssemblerWarning")
@pytest.mark.parametrize("case", _cases("lift", arms_only=True))
def test_the_arm_runs_200_steps_of_robosuites_lift(case: Case, corpus: Corpus) -> None:
    robosuite = pytest.importorskip("robosuite", reason="robosuite is not installed (the robosuite extra)")
    bridge = pytest.importorskip("assembler.robosuite")
    name = corpus.name(case)
    jaws = [str(path) for path in corpus.jaws.get(case.id, ())]
    bridge.register(*jaws, str(corpus.spec(case)))
    env = robosuite.make(
        "Lift", robots=name, has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False
    )
    env.reset()
    for arm in env.robots[0].arms if jaws else ():  # each jaw cut from the file is robosuite's gripper
        assert env.robots[0].gripper[arm].dof >= 1  # with an action of its own
    start = env.sim.data.qpos.copy()
    rng = np.random.default_rng(0)
    for _ in range(200):
        env.step(rng.uniform(-0.2, 0.2, env.action_dim))
    qpos = env.sim.data.qpos
    assert np.all(np.isfinite(qpos)) and not np.allclose(qpos, start)
    env.close()


@pytest.mark.filterwarnings("ignore::assembler.errors.AssemblerWarning")
@pytest.mark.parametrize("case", [p for p in _cases("lift", arms_only=True) if p.values[0].id in TWO_HANDS])
@pytest.mark.parametrize("task", ["TwoArmLift", "Lift"])
def test_each_hand_of_a_bimanual_robot_takes_an_action_that_opens_and_closes_it(
    case: Case, corpus: Corpus, task: str
) -> None:
    """Each hand, cut from its arm into a gripper spec of its own, is robosuite's gripper of that arm:
    the action has one dimension more per hand, and -1 opens it, +1 closes it (the fingers' qpos)."""
    robosuite = pytest.importorskip("robosuite", reason="robosuite is not installed (the robosuite extra)")
    bridge = pytest.importorskip("assembler.robosuite")
    name = corpus.name(case)
    bridge.register(*map(str, corpus.jaws[case.id]), str(corpus.spec(case)))
    options = {"env_configuration": "single-robot"} if task.startswith("TwoArm") else {}
    env = robosuite.make(
        task, robots=name, has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False, **options
    )
    env.reset()
    robot = env.robots[0]
    arms = sum(robot.part_controllers[arm].control_dim for arm in robot.arms)
    assert [robot.gripper[arm].dof for arm in robot.arms] == [1, 1] and env.action_dim == arms + 2
    model = env.sim.model
    fingers = {  # each hand's finger joints, their ranges: which end is open is the file's
        arm: [
            j
            for j in range(model.njnt)
            if model.joint_id2name(j).startswith(robot.gripper[arm].naming_prefix)
        ]
        for arm in robot.arms
    }
    reached = {}
    for value in (-1.0, 1.0):  # open both hands, then close them
        action = robot.create_action_vector({robot.get_gripper_name(arm): [value] for arm in robot.arms})
        for _ in range(30):
            env.step(action)
        reached[value] = env.sim.data.qpos.copy()
    env.close()
    for arm, joints in fingers.items():
        assert joints, arm
        for joint in joints:  # each finger travels at least 90% of its range between open and closed
            address, (low, high) = model.jnt_qposadr[joint], model.jnt_range[joint]
            assert abs(reached[-1.0][address] - reached[1.0][address]) > 0.9 * (high - low), (
                model.joint_id2name(joint)
            )


@pytest.mark.filterwarnings("ignore::assembler.errors.AssemblerWarning")
def test_an_arm_whose_actuators_are_unnamed_is_refused_by_robosuite_in_one_line_naming_them(
    corpus: Corpus, tmp_path: Path
) -> None:
    """gym-aloha's ViperX without the names ``new`` gives its servos: robosuite finds an actuator by its
    name, so the bridge refuses the arm, saying so, where robosuite's Lift would fail at its first step
    (numpy: operands could not be broadcast together with shapes (6,) (0,) (0,))."""
    robosuite = pytest.importorskip("robosuite", reason="robosuite is not installed (the robosuite extra)")
    bridge = pytest.importorskip("assembler.robosuite")
    (case,) = [c for c in CASES if c.id == "aloha_viperx"]
    fields = yaml.safe_load(corpus.spec(case).read_text())
    fields["name"] = "AlohaUnnamedServos"
    fields["mjcf_fixes"] = [fix for fix in fields["mjcf_fixes"] if "name" not in fix.get("set", {})]
    spec = tmp_path / "aloha_unnamed_servos.yaml"
    spec.write_text(yaml.safe_dump(fields, sort_keys=False))
    bridge.register(str(spec))
    with pytest.raises(AssemblerError) as refused:
        robosuite.make(
            "Lift",
            robots="AlohaUnnamedServos",
            has_renderer=False,
            has_offscreen_renderer=False,
            use_camera_obs=False,
        )
    (line,) = str(refused.value).splitlines()
    assert "vx300s_left/waist" in line and "have no name, and robosuite finds an actuator by its name" in line
