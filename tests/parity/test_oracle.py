"""The parity oracle notices every kind of drift: one field of each family is changed in our assembly
(its MjSpec before compiling, or the compiled keyframe) and the oracle must report that field of that
element, and nothing outside the family (but for what the change necessarily moves along).

Lights and contact pairs exist in no robosuite part, so the same light and pair are added to both sides
(robosuite's XML tree and our spec), then ours is changed.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import mujoco
import numpy as np
import pytest

from assembler.mjcf.compose import copy_properties, move_actuators_last
from assembler.models.part import set_joint_attribute_value
from tests.parity.case import Case, build_ours
from tests.parity.cases import renamed
from tests.parity.oracle import differences, families
from tests.parity.robosuite_side import build_edited_reference, build_reference

pytest.importorskip("robosuite", reason='parity needs robosuite: pip install ".[test,robosuite]"')
pytestmark = pytest.mark.parity

PANDA = Case("Panda")
PAD = "gripper0_right_finger1_pad_collision"
ROBOTIQ = Case("Panda", gripper="Robotiq140Gripper")  # tendons and equalities
CPL = "gripper0_right_finger2_12_cpl"
LAMP = "robot0_lamp"


@dataclass(frozen=True)
class Mutation:
    """A change to our assembly, and the start of the line the oracle must report for it."""

    line: str
    """e.g. ``joint robot0_joint3: stiffness``; its first word is the family."""
    edit: Callable[[mujoco.MjSpec], Any] | None = None
    after: Callable[[mujoco.MjModel], Any] | None = None
    case: Case = PANDA
    both: tuple[Callable[[mujoco.MjSpec], Any], Callable[[Any], Any]] | None = None
    """The same element added to our spec and to robosuite's model first (ours, robosuite's)."""
    also: frozenset[str] = field(default_factory=frozenset)
    """Other families the change necessarily moves (a mesh's scale resizes its geoms)."""

    @property
    def family(self) -> str:
        return self.line.split(" ", 1)[0]

    @property
    def id(self) -> str:
        return self.line.replace(" ", "_")


def setter(kind: str, name: str, attribute: str, value: Any) -> Callable[[mujoco.MjSpec], Any]:
    return lambda spec: setattr(getattr(spec, kind)(name), attribute, value)


def joint_value(attribute: str, value: float) -> Callable[[mujoco.MjSpec], Any]:
    """Set a joint attribute the way the assembler does (its MjSpec type changed across MuJoCo versions)."""
    return lambda spec: set_joint_attribute_value(spec.joint("robot0_joint3"), attribute, value)


def _shift_equality_data(spec: mujoco.MjSpec) -> None:
    data = np.array(spec.equality(CPL).data)  # 11 numbers before MuJoCo 4, 12 since
    data[0] += 0.1
    spec.equality(CPL).data = data


def _integrator_with_actrange(spec: mujoco.MjSpec) -> None:
    actuator = spec.actuator("robot0_torq_j3")  # an activation range needs an activation
    actuator.dyntype, actuator.actlimited, actuator.actrange = mujoco.mjtDyn.mjDYN_INTEGRATOR, 1, [-1, 1]


def _reparent_eef(spec: mujoco.MjSpec) -> None:
    """Move the gripper's eef body from the gripper's root onto the robot's hand (MjSpec has no
    re-parenting: attach a copy, delete the original, then restore the copy's names)."""
    spec.copy_during_attach = True
    old = spec.body("gripper0_right_eef")
    copy = spec.body("robot0_right_hand").add_frame().attach_body(old, "moved_", "")
    spec.delete(old)
    for element in [copy, *copy.find_all(mujoco.mjtObj.mjOBJ_SITE)]:
        element.name = element.name.removeprefix("moved_")


def _swap_first_joints(spec: mujoco.MjSpec) -> None:
    """Move the mobile base's first joint after its others (MjSpec has no reorder: re-add it)."""
    body = spec.joint("mobilebase0_joint_mobile_forward").parent
    old = spec.joint("mobilebase0_joint_mobile_forward")
    new = body.add_joint()
    copy_properties(old, new)
    spec.delete(old)
    new.name = "mobilebase0_joint_mobile_forward"


def _light(spec: mujoco.MjSpec) -> Any:
    return spec.body("robot0_link3").add_light(name=LAMP, pos=[0.1, 0, 0], diffuse=[0.5, 0.5, 0.5])


def _their_light(robot: Any) -> None:
    body = robot.worldbody.find(".//body[@name='robot0_link3']")
    body.append(ET.Element("light", name=LAMP, pos="0.1 0 0", diffuse="0.5 0.5 0.5"))


def _pair(spec: mujoco.MjSpec) -> Any:
    return spec.add_pair(geomname1=PAD, geomname2=PAD.replace("1", "2"), margin=0.01)


def _their_pair(robot: Any) -> None:
    robot.contact.append(ET.Element("pair", geom1=PAD, geom2=PAD.replace("1", "2"), margin="0.01"))


def _edit_pair(spec: mujoco.MjSpec) -> None:
    spec.pairs[-1].margin = 0.02


LIGHT = (_light, _their_light)


MUTATIONS = [
    Mutation("body robot0_link3: mass", setter("body", "robot0_link3", "mass", 5.0)),
    Mutation("body robot0_link3: inertia", setter("body", "robot0_link3", "inertia", [0.1, 0.2, 0.3])),
    Mutation("body robot0_link3: inertial frame", setter("body", "robot0_link3", "ipos", [0, 0, 0.1])),
    Mutation("body robot0_link3: gravcomp", setter("body", "robot0_link3", "gravcomp", 1.0)),
    Mutation(
        "body gripper0_right_eef: world orientation",
        setter("body", "gripper0_right_eef", "quat", [0, 1, 0, 0]),
        also=frozenset({"site"}),
    ),
    Mutation("body gripper0_right_eef: parent", _reparent_eef, also=frozenset({"site"})),
    Mutation("joint robot0_joint3: axis", setter("joint", "robot0_joint3", "axis", [0, 1, 0])),
    Mutation("joint robot0_joint3: anchor", setter("joint", "robot0_joint3", "pos", [0, 0, 0.01])),
    Mutation("joint robot0_joint3: stiffness", joint_value("stiffness", 5.0)),
    Mutation("joint robot0_joint3: springref", setter("joint", "robot0_joint3", "springref", 0.3)),
    Mutation("joint robot0_joint3: solref", setter("joint", "robot0_joint3", "solref_limit", [0.05, 1])),
    Mutation("joint robot0_joint3: solimp", setter("joint", "robot0_joint3", "solimp_limit", [0.8] * 5)),
    Mutation("joint robot0_joint3: margin", setter("joint", "robot0_joint3", "margin", 0.01)),
    Mutation("joint robot0_joint3: range", setter("joint", "robot0_joint3", "range", [-1, 1])),
    Mutation("joint robot0_joint3: armature", joint_value("armature", 0.7)),
    Mutation("joint robot0_joint3: damping", joint_value("damping", 0.7)),
    Mutation("joint robot0_joint3: frictionloss", joint_value("frictionloss", 0.7)),
    Mutation(
        "joint robot0_joint3: friction solref", setter("joint", "robot0_joint3", "solref_friction", [0.05, 1])
    ),
    Mutation("joint robot0_joint3: group", setter("joint", "robot0_joint3", "group", 4)),
    Mutation(f"geom {PAD}: size", setter("geom", PAD, "size", [0.01, 0.01, 0.01])),
    Mutation(f"geom {PAD}: world position", setter("geom", PAD, "pos", [0, 0.01, 0.02])),
    Mutation(f"geom {PAD}: world orientation", setter("geom", PAD, "quat", [0.6, 0.8, 0, 0])),
    Mutation(f"geom {PAD}: friction", setter("geom", PAD, "friction", [0.5, 0.01, 0.001])),
    Mutation(f"geom {PAD}: solref", setter("geom", PAD, "solref", [0.05, 1])),
    Mutation(f"geom {PAD}: solimp", setter("geom", PAD, "solimp", [0.8] * 5)),
    Mutation(f"geom {PAD}: condim", setter("geom", PAD, "condim", 6)),
    Mutation(f"geom {PAD}: priority", setter("geom", PAD, "priority", 2)),
    Mutation(f"geom {PAD}: margin", setter("geom", PAD, "margin", 0.01)),
    Mutation(f"geom {PAD}: gap", setter("geom", PAD, "gap", 0.01)),
    Mutation(f"geom {PAD}: contype", setter("geom", PAD, "contype", 4)),
    Mutation(f"geom {PAD}: rgba", setter("geom", PAD, "rgba", [1, 0, 0, 1])),
    Mutation(
        "geom robot0_link0_collision: mesh",
        setter("geom", "robot0_link0_collision", "meshname", "robot0_link1"),
    ),
    Mutation(
        "geom robot0_link0_collision: material",
        setter("geom", "robot0_link0_collision", "material", "robot0_Shell_001"),
    ),
    Mutation(
        "site gripper0_right_ee_x: size", setter("site", "gripper0_right_ee_x", "size", [0.1, 0.1, 0.1])
    ),
    Mutation(
        "site gripper0_right_ee_x: world position", setter("site", "gripper0_right_ee_x", "pos", [0, 0, 0.3])
    ),
    Mutation(
        "site gripper0_right_ee_x: world orientation",
        setter("site", "gripper0_right_ee_x", "quat", [0, 0, 1, 0]),
    ),
    Mutation(
        "camera robot0_eye_in_hand: world position",
        setter("camera", "robot0_eye_in_hand", "pos", [0, 0, 0.3]),
    ),
    Mutation(
        "camera robot0_eye_in_hand: world orientation",
        setter("camera", "robot0_eye_in_hand", "quat", [0, 0, 1, 0]),
    ),
    Mutation("camera robot0_eye_in_hand: fovy", setter("camera", "robot0_eye_in_hand", "fovy", 30.0)),
    Mutation(
        f"light {LAMP}: diffuse", lambda spec: setattr(spec.light(LAMP), "diffuse", [1, 0, 0]), both=LIGHT
    ),
    Mutation(
        f"light {LAMP}: world position",
        lambda spec: setattr(spec.light(LAMP), "pos", [0, 0.1, 0]),
        both=LIGHT,
    ),
    Mutation(
        "actuator robot0_torq_j3: gear", setter("actuator", "robot0_torq_j3", "gear", [2, 0, 0, 0, 0, 0])
    ),
    Mutation(
        "actuator robot0_torq_j3: ctrlrange", setter("actuator", "robot0_torq_j3", "ctrlrange", [-1, 1])
    ),
    Mutation(
        "actuator robot0_torq_j3: forcerange", setter("actuator", "robot0_torq_j3", "forcerange", [-1, 1])
    ),
    Mutation("actuator robot0_torq_j3: actrange", _integrator_with_actrange),
    Mutation(
        "actuator robot0_torq_j3: gainprm", setter("actuator", "robot0_torq_j3", "gainprm", [3.0] + [0.0] * 9)
    ),
    Mutation(
        "actuator robot0_torq_j3: biasprm",
        setter("actuator", "robot0_torq_j3", "biasprm", [0.0, 0.0, -1.0] + [0.0] * 7),
    ),
    Mutation(
        "actuator robot0_torq_j3: dynprm", setter("actuator", "robot0_torq_j3", "dynprm", [2.0] + [0.0] * 9)
    ),
    Mutation(
        "actuator robot0_torq_j3: dyntype",
        setter("actuator", "robot0_torq_j3", "dyntype", mujoco.mjtDyn.mjDYN_FILTER),
    ),
    Mutation(
        "actuator robot0_torq_j3: gaintype",
        setter("actuator", "robot0_torq_j3", "gaintype", mujoco.mjtGain.mjGAIN_AFFINE),
    ),
    Mutation(
        "actuator robot0_torq_j3: biastype",
        setter("actuator", "robot0_torq_j3", "biastype", mujoco.mjtBias.mjBIAS_AFFINE),
    ),
    Mutation(
        "actuator robot0_torq_j3: transmission",
        setter("actuator", "robot0_torq_j3", "target", "robot0_joint4"),
    ),
    Mutation("order actuators: robot0_torq_j2", lambda spec: move_actuators_last(spec, ["robot0_torq_j1"])),
    Mutation("order joints: mobilebase0_joint_mobile_side", _swap_first_joints, case=Case("PandaOmron")),
    Mutation(
        "sensor gripper0_right_force_ee: noise", setter("sensor", "gripper0_right_force_ee", "noise", 0.1)
    ),
    Mutation(
        "sensor gripper0_right_force_ee: cutoff", setter("sensor", "gripper0_right_force_ee", "cutoff", 9.0)
    ),
    Mutation(
        "sensor gripper0_right_force_ee: object",
        setter("sensor", "gripper0_right_force_ee", "objname", "gripper0_right_grip_site"),
    ),
    Mutation(
        f"tendon {CPL}: stiffness",
        lambda spec: set_joint_attribute_value(spec.tendon(CPL), "stiffness", 3.0),
        case=ROBOTIQ,
    ),
    Mutation(
        f"tendon {CPL}: damping",
        lambda spec: set_joint_attribute_value(spec.tendon(CPL), "damping", 3.0),
        case=ROBOTIQ,
    ),
    Mutation(f"tendon {CPL}: width", setter("tendon", CPL, "width", 0.1), case=ROBOTIQ),
    Mutation(
        f"tendon {CPL}: path",
        lambda spec: spec.tendon(CPL).wrap_joint("robot0_joint7", 0.5),
        case=ROBOTIQ,
    ),
    Mutation(f"equality {CPL}: solref", setter("equality", CPL, "solref", [0.05, 1]), case=ROBOTIQ),
    Mutation(f"equality {CPL}: data", _shift_equality_data, case=ROBOTIQ),
    Mutation(f"equality {CPL}: active", setter("equality", CPL, "active", False), case=ROBOTIQ),
    Mutation(f"contact pair {PAD}", _edit_pair, both=(_pair, _their_pair)),
    Mutation(
        "contact exclude robot0_link1 + robot0_link2",
        lambda spec: spec.add_exclude(bodyname1="robot0_link1", bodyname2="robot0_link2"),
    ),
    Mutation("keyframe home: qpos of joint robot0_joint2", after=lambda m: m.key_qpos[0].__setitem__(1, 0.5)),
    Mutation(
        "keyframe home: ctrl of actuator robot0_torq_j2", after=lambda m: m.key_ctrl[0].__setitem__(1, 0.5)
    ),
    Mutation("option timestep:", lambda spec: setattr(spec.option, "timestep", 0.001)),
    Mutation("option gravity:", lambda spec: setattr(spec.option, "gravity", [0, 0, -1])),
    Mutation(
        "mesh robot0_link1: scale",
        setter("mesh", "robot0_link1", "scale", [1.1, 1.1, 1.1]),
        also=frozenset({"geom"}),
    ),
    Mutation("material robot0_Shell_001: rgba", setter("material", "robot0_Shell_001", "rgba", [1, 0, 0, 1])),
    Mutation(
        "texture gripper0_right_carbon_tex: size",
        setter("texture", "gripper0_right_carbon_tex", "width", 7),
        case=Case("Panda", gripper="JacoThreeFingerGripper"),
    ),
]


@pytest.mark.parametrize("mutation", MUTATIONS, ids=[m.id for m in MUTATIONS])
def test_the_oracle_reports_a_change_of_each_field_family(mutation: Mutation) -> None:
    case = mutation.case
    ours_first, theirs_first = mutation.both or (None, None)
    reference = build_edited_reference(case, theirs_first) if theirs_first else build_reference(case)
    unchanged = set(differences(build_ours(case, ours_first), reference, renamed(case)))

    def edit(spec: mujoco.MjSpec) -> None:
        if ours_first is not None:
            ours_first(spec)
        if mutation.edit is not None:
            mutation.edit(spec)

    model = build_ours(case, edit)
    if mutation.after is not None:
        mutation.after(model)
    new = [line for line in differences(model, reference, renamed(case)) if line not in unchanged]
    assert any(line.startswith(mutation.line) for line in new), f"{mutation.line!r} not in {new}"
    assert families(new) <= {mutation.family} | mutation.also, new


def test_a_stored_reference_is_robosuites_model_and_a_new_mujoco_or_case_is_a_miss(
    tmp_path: Any, monkeypatch: pytest.MonkeyPatch
) -> None:
    """robosuite's side is kept between runs (CI keeps it); what comes back from the store must be the
    model robosuite builds, and nothing else may be served under a case's name."""
    from tests.parity import robosuite_side

    monkeypatch.setenv(robosuite_side.REFERENCE_FOLDER_VARIABLE, str(tmp_path))
    built = build_reference(PANDA)
    stored_files = sorted(tmp_path.glob("*.npz"))
    stored = build_reference(PANDA)
    assert len(stored_files) == 1 and stored_files == sorted(tmp_path.glob("*.npz"))
    assert robosuite_side._model_bytes(stored.model) == robosuite_side._model_bytes(built.model)
    assert np.array_equal(stored.home_qpos, built.home_qpos) and np.array_equal(
        stored.home_ctrl, built.home_ctrl
    )
    assert differences(build_ours(PANDA), stored, renamed(PANDA)) == differences(
        build_ours(PANDA), built, renamed(PANDA)
    )
    build_reference(Case("Panda", idn=1))
    monkeypatch.setattr(robosuite_side.mujoco, "__version__", "0.0.1")
    build_reference(PANDA)
    assert len(list(tmp_path.glob("*.npz"))) == 3
