"""The shipped motor catalogue: every motor spec validates and cites its source, and the shipped
Unitree robots get the armature mjlab's constants give (computed here from the numbers mjlab cites,
with mjlab's own formulas), and their motors' torque limits as force ranges; the maxon RE 25 with its
GP 26 B gearhead gives a joint the armature and limit its catalogue pages give."""

from __future__ import annotations

import pytest

from assembler.files.paths import shipped_specs_dir
from assembler.models.motor_table import MOTORS
from assembler.registry.lookup import registered_class, robot_class
from assembler.spec.spec_files import load_motors, read_spec_files
from assembler.urdf.packages import package_folders
from tests.motors.rigs import Write, motor_robot

NEEDS_URDFS = pytest.mark.skipif(
    not package_folders("example-robot-data"), reason="the shipped Go2 and G1 read example-robot-data's URDFs"
)

SHIPPED = load_motors(read_spec_files([shipped_specs_dir() / "motors"]).motors)


def reflected_inertia(rotor_inertia: float, gear_ratio: float) -> float:
    """mjlab's ``mjlab.utils.actuator.reflected_inertia``."""
    return rotor_inertia * gear_ratio**2


def reflected_inertia_from_two_stage_planetary(
    rotor_inertia: tuple[float, float, float], gear_ratio: tuple[float, float, float]
) -> float:
    """mjlab's ``mjlab.utils.actuator.reflected_inertia_from_two_stage_planetary``."""
    assert gear_ratio[0] == 1
    r1 = rotor_inertia[0] * (gear_ratio[1] * gear_ratio[2]) ** 2
    r2 = rotor_inertia[1] * gear_ratio[2] ** 2
    return r1 + r2 + rotor_inertia[2]


# mjlab go1_constants.py (commit 0eda4e7): ROTOR_INERTIA, HIP_GEAR_RATIO, KNEE_GEAR_RATIO, effort and
# velocity limits (the last are the URDF's, which MuJoCo keeps as no joint field: checked on the URDF).
GO1_ROTOR_INERTIA = 0.000111842
GO1 = {"hip": (6, 23.7, 30.1), "thigh": (6, 23.7, 30.1), "calf": (6 * 1.5, 35.55, 20.06)}

# mjlab go2_constants.py (commit 3c5e2ea): ROTOR_INERTIA, HIP_GEAR_RATIO, KNEE_GEAR_RATIO, effort limits.
GO2_ROTOR_INERTIA = 0.000111842
GO2 = {"hip": (6, 23.7), "thigh": (6, 23.7), "calf": (6 * 1.5, 45.43)}

# mjlab g1_constants.py (commit 0eda4e7): Unitree's rotor and stage inertias and stage ratios, effort limits.
G1_MOTORS = {
    "5020": ((0.139e-4, 0.017e-4, 0.169e-4), (1, 1 + (46 / 18), 1 + (56 / 16)), 25.0),
    "7520_14": ((0.489e-4, 0.098e-4, 0.533e-4), (1, 4.5, 1 + (48 / 22)), 88.0),
    "7520_22": ((0.489e-4, 0.109e-4, 0.738e-4), (1, 4.5, 5), 139.0),
    "4010": ((0.068e-4, 0.0, 0.0), (1, 5, 5), 5.0),
}
G1_JOINTS = {  # mjlab's G1_ACTUATOR_* joint_names_expr (ankles and waist roll/pitch: a linkage, no motor here)
    "left_hip_pitch_joint": "7520_14",
    "right_hip_yaw_joint": "7520_14",
    "waist_yaw_joint": "7520_14",
    "left_hip_roll_joint": "7520_22",
    "right_knee_joint": "7520_22",
    "left_shoulder_pitch_joint": "5020",
    "right_elbow_joint": "5020",
    "left_wrist_roll_joint": "5020",
    "right_wrist_pitch_joint": "4010",
    "left_wrist_yaw_joint": "4010",
}


def test_the_catalogue_ships_at_least_twelve_motors_each_with_its_source() -> None:
    assert len(SHIPPED) >= 12
    for loaded in SHIPPED:
        assert loaded.spec.source.strip(), loaded.source
        text = loaded.document.path.read_text()  # type: ignore[union-attr]
        assert text.count("\n#") >= 2, f"{loaded.source}: say where the values come from in a comment"


# correlllab/h12-lab-docs docs/specs.md (commit 071574a): M107 output total equivalent moments (kg m^2).
M107_TOTALS = {"UnitreeM107_15": (15, 0.063259741), "UnitreeM107_24": (24, 0.160478022)}


@pytest.mark.parametrize("name", sorted(M107_TOTALS))
def test_the_m107_motors_give_the_equivalent_moment_their_table_gives(name: str) -> None:
    ratio, total = M107_TOTALS[name]
    motor = MOTORS.lookup(name).spec
    assert motor.gear_ratio == ratio
    assert motor.rotor_inertia is not None and motor.gearbox_inertia is not None
    assert motor.rotor_inertia * ratio**2 + motor.gearbox_inertia == pytest.approx(total, rel=1e-12)


def test_every_shipped_motor_is_found_by_name() -> None:
    assert {loaded.spec.name for loaded in SHIPPED} <= set(MOTORS.names())


# maxon's catalogue pages (specs/motors/maxon_re25_gp26b.yaml): the RE 25's rotor inertia (118752) and the
# GP 26 B's mass inertia referred to the motor shaft, its reduction and intermittent output torque (144039).
RE25_ROTOR_INERTIA = 10.8e-7  # kg m²: 10.8 g cm²
GP26B_INERTIA_AT_MOTOR = 0.4e-7  # kg m²: 0.4 g cm²
GP26B_RATIO, GP26B_INTERMITTENT_TORQUE = 84, 1.9


def test_the_maxon_re25_with_its_gp26b_gives_the_joint_both_inertias_through_84_squared(write: Write) -> None:
    robot = motor_robot(write, "{match: spin, motor: MaxonRE25GP26B, control: torque}")
    model = robot.get_model()
    # both inertias are at the motor shaft: each is seen at the joint times the ratio squared
    armature = (RE25_ROTOR_INERTIA + GP26B_INERTIA_AT_MOTOR) * GP26B_RATIO**2
    assert model.joint(robot.naming_prefix + "spin").armature[0] == pytest.approx(armature, rel=1e-12)
    # the gearhead's output rating, not the 12 N·m the motor's stall torque would give through it
    limit = GP26B_INTERMITTENT_TORQUE
    assert model.actuator(robot.naming_prefix + "spin").forcerange.tolist() == pytest.approx([-limit, limit])


@NEEDS_URDFS
@pytest.mark.parametrize("part", sorted(GO1))
def test_go1_with_its_shipped_motors_has_the_armature_effort_and_velocity_of_mjlab_go1(part: str) -> None:
    base = registered_class("base", "Go1")(idn=0)
    model = base.compile_alone()
    ratio, effort, velocity = GO1[part]
    for leg in ("FL", "FR", "RL", "RR"):
        joint = f"{leg}_{part}_joint"
        armature = model.joint(base.naming_prefix + joint).armature[0]
        assert armature == pytest.approx(reflected_inertia(GO1_ROTOR_INERTIA, ratio), rel=1e-12)
        actuator = model.actuator(base.naming_prefix + joint)
        assert actuator.forcerange.tolist() == pytest.approx([-effort, effort], rel=1e-12)
        assert base.source.velocity_limits[joint] == velocity


@NEEDS_URDFS
@pytest.mark.parametrize("part", sorted(GO2))
def test_go2_with_its_shipped_motors_has_the_armature_and_effort_of_mjlab_go2(part: str) -> None:
    base = registered_class("base", "Go2")(idn=0)
    model = base.compile_alone()
    ratio, effort = GO2[part]
    for leg in ("FL", "FR", "RL", "RR"):
        joint = model.joint(f"{base.naming_prefix}{leg}_{part}_joint")
        assert joint.armature[0] == pytest.approx(reflected_inertia(GO2_ROTOR_INERTIA, ratio), rel=1e-12)
        actuator = model.actuator(f"{base.naming_prefix}{leg}_{part}_joint")
        assert actuator.forcerange.tolist() == pytest.approx([-effort, effort], rel=1e-12)


@NEEDS_URDFS
@pytest.mark.parametrize(("joint", "motor"), sorted(G1_JOINTS.items()))
def test_g1_with_its_shipped_motors_has_the_armature_and_effort_of_mjlab_g1(joint: str, motor: str) -> None:
    robot = robot_class("G1")(idn=0)
    inertias, ratios, effort = G1_MOTORS[motor]
    value = robot.joint_values[joint]["armature"]
    assert value.value == pytest.approx(
        reflected_inertia_from_two_stage_planetary(inertias, ratios), rel=1e-12
    )
    (record,) = [r for r in robot.actuator_table if r.joint == joint]
    limit = dict(record.derivations)["forcerange"].value
    assert limit == effort


# LeRobot's SO-101 assembly guide (https://huggingface.co/docs/lerobot/so101): "The follower arm uses 6x
# STS3215 motors with 1/345 gearing." MuJoCo Menagerie's so_arm100.xml: armature 0.1, frictionloss 0.1.
SO101_JOINTS = ("shoulder_pan", "shoulder_lift", "elbow_flex", "wrist_flex", "wrist_roll", "gripper")
SO101_GEAR_RATIO = 345
SO101_ARMATURE = SO101_FRICTIONLOSS = 0.1


@NEEDS_URDFS
def test_so101_names_the_sts3215_on_every_joint_its_stall_torque_the_servos_force_limit() -> None:
    robot = robot_class("SO101")(idn=0)
    motor = MOTORS.lookup("FeetechSTS3215").spec
    assert motor.gear_ratio == SO101_GEAR_RATIO and motor.ratings_at == "output"
    assert motor.peak_torque is None and motor.stall_torque is not None
    model = robot.get_model()
    for joint in SO101_JOINTS:
        (record,) = [r for r in robot.actuator_table if r.joint == joint]
        assert (record.section, record.type) == ("motors", "position")
        assert record.values["forcerange"][1] == "motor FeetechSTS3215"
        actuator = model.actuator(robot.naming_prefix + joint)
        # the spec's own gearbox: the output's stall torque is the joint's
        assert actuator.forcerange.tolist() == pytest.approx(
            [-motor.stall_torque, motor.stall_torque], rel=1e-12
        )
        compiled = model.joint(robot.naming_prefix + joint)
        assert (compiled.armature[0], compiled.frictionloss[0]) == (SO101_ARMATURE, SO101_FRICTIONLOSS)
