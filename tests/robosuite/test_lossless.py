"""What robosuite's XML layer reads for a part is exactly our part.

robosuite reads each robot, gripper and base from a file through its own XML layer, which keeps only
literal attributes and top-level classes and re-applies its joint values where an attribute is
missing. Every shipped part, written for it (``assembler/robosuite/lossless.py``) and compiled the
way robosuite compiles a part, must give the very model our own compile of that part gives: every
field, every element, bit for bit.
"""

from __future__ import annotations

import pytest

robosuite = pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

import mujoco  # noqa: E402

import assembler.robosuite  # noqa: E402, F401
from assembler.errors import MissingPackageError  # noqa: E402
from assembler.models import REGISTRIES, PartModel  # noqa: E402
from assembler.robosuite.conventions import offered  # noqa: E402
from assembler.robosuite.part_classes import robosuite_class_of  # noqa: E402
from assembler.robosuite.parts import robosuite_part  # noqa: E402
from assembler.robosuite.registrations import family_of  # noqa: E402
from assembler.robosuite.robot_class import robot_class  # noqa: E402
from tests.robosuite.exact import differences  # noqa: E402

PARTS = sorted(
    (family, name)
    for family, table in REGISTRIES.items()
    for name, cls in table.items()
    if offered(cls) and (family != "robot" or cls.spec.arms)
)
"""Every part robosuite is offered (FrankaPanda's spec keeps it out, and test_our_robots says why)."""


def _ours(cls: type[PartModel]) -> mujoco.MjModel:
    """Our compile of the part robosuite is given (robosuite's geom names, declared arm actuation)."""
    return robosuite_part(cls).part_mjspec().compile()


def _theirs(cls: type[PartModel]) -> mujoco.MjModel:
    """robosuite's compile of the same part, read through its XML layer from the file we write."""
    made = robot_class(cls) if family_of(cls) == "robot" else robosuite_class_of(cls)
    return made(idn=0).get_model()


DOES_NOT_COMPILE_ALONE: dict[str, str] = {
    "NullMobileBase": "mass and inertia of moving bodies must be larger than mjMINVAL",
}
"""Parts MuJoCo refuses alone, with its reason: robosuite never compiles them alone either (a mobile
base's massless support moves only with the robot on it)."""


# A part whose model file lacks the frames robosuite looks up gets them for robosuite, said in a
# warning (grip_frames.py, arm_centers.py); the part with them is what both sides must read alike.
@pytest.mark.filterwarnings("ignore:.*model file lacks:assembler.errors.AssemblerWarning")
@pytest.mark.parametrize(("family", "name"), PARTS, ids=[f"{f}-{n}" for f, n in PARTS])
def test_robosuite_reads_every_part_as_we_build_it(family: str, name: str) -> None:
    cls = REGISTRIES[family][name]
    if name in DOES_NOT_COMPILE_ALONE:
        with pytest.raises(ValueError, match=DOES_NOT_COMPILE_ALONE[name]):
            _ours(cls)
        pytest.skip(
            f"{name} does not compile alone ({DOES_NOT_COMPILE_ALONE[name]}); robosuite never does that"
        )
    try:
        ours = _ours(cls)
    except MissingPackageError as error:  # a URDF part without the urdf extra: one line says which
        pytest.skip(f"{name} needs a package that is not installed: {error}")
    assert differences(ours, _theirs(cls)) == []
