"""Registration with robosuite as a user meets it: import, replace, register a folder, run a script.

robosuite's registries are module globals, so every case runs in its own Python process (the test's
interpreter, this checkout first on ``PYTHONPATH``) and reports what it saw as one JSON line. Nothing
is mocked: robosuite is imported, its tables are read after our import, environments are made.
"""

from __future__ import annotations

import json
import pkgutil
import subprocess
import sys
import sysconfig
from pathlib import Path
from typing import Any

import pytest

import assembler.robosuite
from assembler.urdf.packages import package_folders

pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')

from tests.robosuite.processes import result as _result  # noqa: E402
from tests.robosuite.processes import run as _run  # noqa: E402
from tests.robosuite.processes import user_folder as _user_folder  # noqa: E402

URDF = bool(package_folders("example-robot-data"))

ROBOT_TYPES = {
    "Sparrow7": "FixedBaseRobot",  # on Pedestal, a mount
    "Finch6": "FixedBaseRobot",
    "TwinTorso": "FixedBaseRobot",  # no base: robosuite's NullMount stands in
    "Biped": "LeggedRobot",  # humanoids drive their legs
    "BipedFree": "LeggedRobot",
}
# FrankaPanda's spec says robosuite.enabled: false (its hand is in its URDF): it is not offered
ROBOT_TYPES |= {"UR5": "FixedBaseRobot", "SO101": "FixedBaseRobot"} if URDF else {}
ROBOT_TYPES |= {"G1": "LeggedRobot"} if URDF else {}
GRIPPERS = {"PincerGripper", "BareFlange", "TriHand"} | ({"AllegroRightHand"} if URDF else set())
BASES = {
    "Pedestal": "MountModel",
    "RoverBase": "MobileBaseModel",
    "QuadrupedBase": "LegBaseModel",
    "SiteOnlyBase": "NullBaseModel",
}
BASES |= {"Go1": "LegBaseModel", "Go2": "LegBaseModel"} if URDF else {}


# ----- the shipped specs, on import --------------------------------------------------------------

AFTER_IMPORT = """
import json, robosuite
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.robots import ROBOT_CLASS_MAPPING
from robosuite.models.grippers import GRIPPER_MAPPING, GripperModel
from robosuite.models.bases import BASE_MAPPING, LegBaseModel, MobileBaseModel, MountModel, NullBaseModel
tables = {"robot": REGISTERED_ROBOTS, "type": ROBOT_CLASS_MAPPING, "gripper": GRIPPER_MAPPING, "base": BASE_MAPPING}
stock = {family: dict(table) for family, table in tables.items()}

import assembler.robosuite
from robosuite.models.robots import create_robot
from assembler.models import REGISTRIES

held = {family: sorted(table.held_names()) for family, table in REGISTRIES.items()}

new = {family: sorted(set(table) - set(stock[family])) for family, table in tables.items()}
kinds = (MountModel, MobileBaseModel, LegBaseModel, NullBaseModel)
env = robosuite.make("Lift", robots="Panda", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
print("RESULT " + json.dumps({
    "new": new,
    "robot_types": {name: ROBOT_CLASS_MAPPING[name].__name__ for name in new["robot"]},
    "robot_specs": {name: REGISTERED_ROBOTS[name].assembler_class.spec.name for name in new["robot"]},
    "all_robots": sorted(set(robosuite.ALL_ROBOTS)),
    "created": type(create_robot("Sparrow7", idn=0)).__name__,
    "grippers": {name: issubclass(GRIPPER_MAPPING[name], GripperModel) for name in new["gripper"]},
    "bases": {name: [k.__name__ for k in kinds if issubclass(BASE_MAPPING[name], k)] for name in new["base"]},
    "changed": sorted(
        f"{family}:{name}" for family, table in stock.items() for name, cls in table.items()
        if tables[family][name] is not cls
    ),
    "null_gripper": [GRIPPER_MAPPING[None] is stock["gripper"][None], GRIPPER_MAPPING[None].__module__],
    "held": held,
    "robosuites": {family: sorted(name or "NullGripper" for name in table) for family, table in stock.items()},
    "lift_panda": type(env.robots[0].robot_model).__module__,
    "panda_controller": robosuite.load_composite_controller_config(robot="Panda")["body_parts"]["right"]["type"],
    "shipped": {family: sorted(table) for family, table in REGISTRIES.items()},
}))
"""


@pytest.fixture(scope="module")
def after_import(tmp_path_factory: pytest.TempPathFactory) -> Any:
    return _result(AFTER_IMPORT, tmp_path_factory.mktemp("import"))


def _not_robosuites(expected: dict[str, Any], after_import: Any, family: str) -> dict[str, Any]:
    """``expected`` without the names robosuite had before the bridge: its own, and those of packages
    that register with it when it loads (robosuite-models' G1 and Go2, installed with the corpus
    extra). The bridge leaves those to robosuite (see test_robosuites_own_names_...)."""
    return {name: value for name, value in expected.items() if name not in after_import["robosuites"][family]}


def test_importing_the_bridge_registers_every_shipped_robot_with_the_robot_type_of_its_base(
    after_import: Any,
) -> None:
    robot_types = _not_robosuites(ROBOT_TYPES, after_import, "robot")
    assert after_import["robot_types"] == robot_types
    assert after_import["new"]["type"] == sorted(robot_types)
    assert after_import["robot_specs"] == {name: name for name in robot_types}
    assert set(ROBOT_TYPES) <= set(after_import["all_robots"])
    assert after_import["created"] == "Sparrow7"  # robosuite.models.robots.create_robot builds it


def test_importing_the_bridge_registers_every_shipped_gripper_and_base_as_robosuites_kind(
    after_import: Any,
) -> None:
    assert after_import["grippers"] == dict.fromkeys(GRIPPERS, True)
    bases = _not_robosuites(BASES, after_import, "base")
    assert after_import["bases"] == {name: [kind] for name, kind in bases.items()}


def test_robosuites_own_names_still_mean_robosuites_classes_after_the_import(after_import: Any) -> None:
    assert after_import["changed"] == []
    assert after_import["null_gripper"] == [True, "robosuite.models.grippers.null_gripper"]
    assert after_import["lift_panda"] == "robosuite.models.robots.manipulators.panda_robot"
    assert after_import["panda_controller"] == "OSC_POSE"


def test_the_import_reads_no_spec_of_a_name_robosuite_uses_itself(after_import: Any) -> None:
    # only replace_robosuite() installs those, and a lookup reads one when it is asked for
    held = after_import["held"]
    assert {"Panda", "GR1"} <= set(held["robot"]) and "PandaGripper" in held["gripper"]
    assert "RethinkMount" in held["base"]
    for family, names in held.items():  # every shipped name robosuite has stays unread (others may
        # stay unread too: a process with current registration records reads none of them), but the
        # bases robots without one stand on, read to record those robots' Robot types
        robosuites = set(after_import["robosuites"][family]) & set(after_import["shipped"][family])
        assert robosuites - {"NullMount", "NoActuationBase"} <= set(names), family


# ----- replacing robosuite's own ------------------------------------------------------------------

REPLACE = """
import json, logging, robosuite
records = []
handler = logging.Handler()
handler.emit = lambda record: records.append(record.getMessage())
logging.getLogger("assembler.robosuite").addHandler(handler)
logging.getLogger("assembler.robosuite").setLevel(logging.INFO)
import assembler.robosuite
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.models.grippers import GRIPPER_MAPPING
import robosuite.models.robots
returned = assembler.robosuite.replace_robosuite(["Panda"])
env = robosuite.make("Lift", robots="Panda", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
print("RESULT " + json.dumps({
    "returned": returned,
    "replaced": assembler.robosuite.replaced(),
    "logged": records,
    "panda": [REGISTERED_ROBOTS["Panda"].__module__, robosuite.models.robots.Panda is REGISTERED_ROBOTS["Panda"]],
    "others": sorted({REGISTERED_ROBOTS[n].__module__.split(".")[0] for n in ("Sawyer", "IIWA", "Baxter")}),
    "panda_gripper": GRIPPER_MAPPING["PandaGripper"].__module__.split(".")[0],
    "in_lift": type(env.robots[0].robot_model).__module__,
}))
"""


def test_replace_robosuite_replaces_only_the_names_asked_for_and_says_so(tmp_path: Path) -> None:
    seen = _result(REPLACE, tmp_path)
    assert seen["returned"] == ["Panda"]
    assert seen["replaced"] == ["Panda"]
    assert seen["logged"] == ["robosuite's Panda replaced by the specs of the same names"]
    assert seen["panda"] == ["assembler.robosuite.robot_class", True]
    assert seen["others"] == ["robosuite"]
    assert seen["panda_gripper"] == "robosuite"
    assert seen["in_lift"] == "assembler.robosuite.robot_class"


CANNOT_REPLACE = {
    "Pandaa": "replace_robosuite: neither robosuite nor the specs know Pandaa. Did you mean 'Panda'?",
    "Sparrow7": (
        "replace_robosuite: Sparrow7 is not robosuite's; robosuite finds our Sparrow7 by that name already"
    ),
    "LeggedManipulatorModel": (
        "replace_robosuite: robosuite's LeggedManipulatorModel has no spec of that name to replace it"
    ),
}

CANNOT_REPLACE_SCRIPT = """
import json, assembler.robosuite
from assembler.errors import RegistryError
messages = {}
for name in NAMES:
    try:
        assembler.robosuite.replace_robosuite([name])
    except RegistryError as error:
        messages[name] = str(error)
print("RESULT " + json.dumps({"messages": messages, "replaced": assembler.robosuite.replaced()}))
"""


@pytest.fixture(scope="module")
def cannot_replace(tmp_path_factory: pytest.TempPathFactory) -> Any:
    code = CANNOT_REPLACE_SCRIPT.replace("NAMES", repr(sorted(CANNOT_REPLACE)))
    return _result(code, tmp_path_factory.mktemp("replace"))


@pytest.mark.parametrize("name", sorted(CANNOT_REPLACE))
def test_replace_robosuite_with_a_name_it_cannot_replace_says_why_in_one_line(
    name: str, cannot_replace: Any
) -> None:
    assert cannot_replace["messages"][name] == CANNOT_REPLACE[name]
    assert cannot_replace["replaced"] == []


# ----- a user's spec folder -----------------------------------------------------------------------

REGISTER_FOLDER = """
import json, numpy as np, robosuite, assembler.robosuite
names = assembler.robosuite.register("my_robots/")
again = assembler.robosuite.register("my_robots/")
env = robosuite.make("Lift", robots="Heron7", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
observations = env.reset()
for _ in range(10):
    observations, *_ = env.step(np.zeros(env.action_dim))
model = env.robots[0].robot_model
print("RESULT " + json.dumps({
    "names": names,
    "again": again,
    "class": type(model).__name__,
    "file": str(model.assembler_class.loaded.document.path.resolve()),
    "finite": bool(np.all(np.isfinite(observations["robot0_eef_pos"]))),
}))
"""


def test_registering_a_users_spec_folder_makes_lift_work_with_their_robot(tmp_path: Path) -> None:
    folder = _user_folder(tmp_path, "Heron7")
    seen = _result(REGISTER_FOLDER, tmp_path)
    assert seen["names"] == seen["again"] == ["Heron7"]  # the same folder twice changes nothing
    assert seen["class"] == "Heron7"
    assert seen["file"] == str((folder / "heron7.yaml").resolve())
    assert seen["finite"]


CLASH = """
import json, assembler.robosuite
from assembler.errors import RegistryError
from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
from robosuite.models.robots.manipulators.manipulator_model import ManipulatorModel

class Heron8(ManipulatorModel):  # the user's hand-written robosuite class: robosuite registers it
    pass

try:
    assembler.robosuite.register("my_robots/")
    message = None
except RegistryError as error:
    message = str(error)
registered = sorted({"Heron7", "Heron8"} & {n for n, c in REGISTERED_ROBOTS.items() if hasattr(c, "assembler_class")})
import os
os.rename("my_robots/heron8.yaml", "my_robots/heron9.yaml")
with open("my_robots/heron9.yaml") as file:
    text = file.read().replace("name: Heron8", "name: Heron9")
with open("my_robots/heron9.yaml", "w") as file:
    file.write(text)
print("RESULT " + json.dumps({
    "message": message,
    "registered": registered,
    "retry": assembler.robosuite.register("my_robots/"),
}))
"""


def test_a_batch_with_a_name_robosuite_has_registers_none_of_the_batch_and_says_which(tmp_path: Path) -> None:
    _user_folder(tmp_path, "Heron7", "Heron8")
    seen = _result(CLASH, tmp_path)
    assert seen["message"] == (
        "my_robots/heron8.yaml:4:7: name: robosuite's robot 'Heron8' is already __main__.Heron8; rename the spec"
    )
    assert seen["registered"] == []
    assert seen["retry"] == ["Heron7", "Heron9"]


def test_a_spec_named_like_robosuites_robot_is_refused_before_anything_is_registered(tmp_path: Path) -> None:
    _user_folder(tmp_path, "Heron7", "Panda")
    code = """
    import json, assembler.robosuite
    from assembler.errors import RegistryError
    from robosuite.models.robots.robot_model import REGISTERED_ROBOTS
    try:
        assembler.robosuite.register("my_robots/")
    except RegistryError as error:
        print("RESULT " + json.dumps([str(error), "Heron7" in REGISTERED_ROBOTS, REGISTERED_ROBOTS["Panda"].__module__]))
    """
    message, heron_registered, panda = _result(code, tmp_path)
    assert message.startswith("my_robots/panda.yaml:4:7: name: robot 'Panda' is already registered by ")
    assert message.endswith("a different spec; rename one")
    assert "\n" not in message
    assert not heron_registered
    assert panda == "robosuite.models.robots.manipulators.panda_robot"


# ----- scripts nobody edits: environment variables, ``python -m``, the start-up hook ---------------

SCRIPT = """\
import sys
import robosuite

env = robosuite.make("Lift", robots="Heron7", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
env.reset()
print("made", type(env.robots[0].robot_model).__name__, list(env.robots[0].init_qpos), sys.argv[1:])
"""

SPARROW7_HOME = [0.0, -0.785, 0.0, -2.356, 0.0, 1.571, 0.785]


def _script(root: Path) -> Path:
    _user_folder(root, "Heron7")
    script = root / "train.py"
    script.write_text(SCRIPT)
    return script


def _made(done: subprocess.CompletedProcess[str]) -> str:
    assert done.returncode == 0, done.stderr[-3000:]
    (line,) = [line for line in done.stdout.splitlines() if line.startswith("made ")]
    return line


def test_an_unmodified_script_run_with_python_m_gets_the_folder_named_by_the_variable(tmp_path: Path) -> None:
    script = _script(tmp_path)
    alone = _run([str(script)], tmp_path, ASSEMBLER_ROBOSUITE_SPECS="my_robots")
    assert alone.returncode != 0 and "Heron7" in alone.stderr  # robosuite alone does not know it
    done = _run(
        ["-m", "assembler.robosuite", str(script), "--lr", "3e-4"],
        tmp_path,
        ASSEMBLER_ROBOSUITE_SPECS="my_robots",
    )
    assert _made(done) == f"made Heron7 {SPARROW7_HOME} ['--lr', '3e-4']"


def test_an_unmodified_script_run_with_python_m_gets_the_robots_of_the_experiment_named_by_the_variable(
    tmp_path: Path,
) -> None:
    script = _script(tmp_path)
    experiment = tmp_path / "study.yaml"
    experiment.write_text(
        "kind: experiment\nname: study\nrobots:\n"
        "  - robot: my_robots/heron7.yaml\n    overrides:\n      init_qpos[3]: -2.0\n"
    )
    done = _run(
        ["-m", "assembler.robosuite", str(script)], tmp_path, ASSEMBLER_ROBOSUITE_EXPERIMENT=str(experiment)
    )
    home = [*SPARROW7_HOME[:3], -2.0, *SPARROW7_HOME[4:]]
    assert _made(done) == f"made Heron7 {home} []"


def test_the_start_up_hook_installs_into_a_throwaway_venv_works_while_installed_and_is_removed(
    tmp_path: Path,
) -> None:
    script = _script(tmp_path)
    venv = tmp_path / "venv"
    subprocess.run(
        [sys.executable, "-m", "venv", "--without-pip", "--system-site-packages", str(venv)], check=True
    )
    python = str(venv / "bin" / "python")
    site = Path(
        _run(
            ["-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"], tmp_path, python
        ).stdout.strip()
    )
    # This interpreter's packages (robosuite, mujoco) for the throwaway venv, as --system-site-packages
    # would give them were this interpreter not itself a venv.
    parent = sysconfig.get_paths()["purelib"]
    (site / "parent-site.pth").write_text(f"import site; site.addsitedir({parent!r})\n")
    variables = {"ASSEMBLER_ROBOSUITE_SPECS": "my_robots"}

    installed = _run(["-m", "assembler.robosuite", "--install-hook"], tmp_path, python)
    hook = site / "assembler-robosuite.pth"
    assert installed.returncode == 0, installed.stderr
    assert installed.stdout.startswith(f"wrote {hook}: ")
    assert hook.is_file()
    assert _made(_run([str(script)], tmp_path, python, **variables)) == f"made Heron7 {SPARROW7_HOME} []"
    untouched = _run(["-c", "import sys; print('robosuite' in sys.modules)"], tmp_path, python, **variables)
    assert untouched.stdout.strip() == "False"  # a process that never imports robosuite does not get it

    removed = _run(["-m", "assembler.robosuite", "--remove-hook"], tmp_path, python)
    assert removed.stdout.strip() == f"removed {hook}"
    assert not hook.exists()
    after = _run([str(script)], tmp_path, python, **variables)
    assert after.returncode != 0 and "Heron7" in after.stderr


# ----- controller configurations ------------------------------------------------------------------

CONTROLLER_SPECS = {
    "HeronNamed": "robosuite: {actuation: torque, controller: default_iiwa}",
    "HeronDict": "robosuite: {actuation: torque, controller: DICT}",
    "HeronFile": "robosuite: {actuation: torque, controller: heron_controller.json}",
    "HeronGR1": "robosuite: {actuation: torque}",  # robosuite's name rules would give it GR1's whole-body IK
    "FinchRover": "default_base: RoverBase",
}

CONTROLLERS = """
import json, pathlib, robosuite, assembler.robosuite
from assembler.robosuite.controllers import ROBOSUITES_LOADER as robosuites
from robosuite.controllers import load_composite_controller_config as bound_in_controllers
configs = pathlib.Path(robosuite.__file__).parent / "controllers" / "config"
assembler.robosuite.register("my_robots/")
def theirs(name):
    return robosuites(controller=str(configs / "robots" / f"{name}.json"))
pandas = theirs("default_panda")
rover = theirs("default_pandaomron")
env = robosuite.make("Lift", robots="HeronDict", has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
print("RESULT " + json.dumps({
    "named": robosuite.load_composite_controller_config(robot="HeronNamed") == theirs("default_iiwa"),
    "dict": bound_in_controllers(robot="HeronDict") == robosuites(controller="my_robots/joint_position.json"),
    "file": robosuite.load_composite_controller_config(robot="HeronFile") == robosuites(controller="my_robots/heron_controller.json"),
    "sparrow7": robosuite.load_composite_controller_config(robot="Sparrow7") == pandas,
    "heron_gr1": robosuite.load_composite_controller_config(robot="HeronGR1") == pandas,
    "twin_torso": robosuite.load_composite_controller_config(robot="TwinTorso") == theirs("default_baxter"),
    "finch_rover": robosuite.load_composite_controller_config(robot="FinchRover"),
    "panda_right": pandas["body_parts"]["right"],
    "rover_base": rover["body_parts"]["base"],
    "in_lift": type(env.robots[0].part_controllers["right"]).__name__,
}))
"""


def test_a_spec_robots_declared_or_default_controller_is_what_robosuites_loader_returns(
    tmp_path: Path,
) -> None:
    import robosuite

    folder = _user_folder(tmp_path, *[name for name in CONTROLLER_SPECS if name != "FinchRover"])
    configs = Path(robosuite.__file__).parent / "controllers" / "config"
    joint_position = json.loads((configs / "default" / "parts" / "joint_position.json").read_text())
    composite = {
        "type": "BASIC",
        "body_parts": {"arms": {"right": {**joint_position, "gripper": {"type": "GRIP"}}}},
    }
    (folder / "joint_position.json").write_text(json.dumps(composite))
    velocity = json.loads((configs / "default" / "parts" / "joint_velocity.json").read_text())
    in_file = {"type": "BASIC", "body_parts": {"arms": {"right": {**velocity, "gripper": {"type": "GRIP"}}}}}
    (folder / "heron_controller.json").write_text(json.dumps(in_file))
    for name, line in CONTROLLER_SPECS.items():
        path = folder / f"{name.lower()}.yaml"
        if name == "FinchRover":
            path.write_text(f"name: FinchRover\nextends: Finch6\n{line}\n")
            continue
        text = path.read_text().replace("robosuite:\n  actuation: torque\n", "")
        path.write_text(text + line.replace("DICT", json.dumps(composite)) + "\n")

    seen = _result(CONTROLLERS, tmp_path)
    assert {key: seen[key] for key in ("named", "dict", "file", "sparrow7", "heron_gr1", "twin_torso")} == {
        "named": True,
        "dict": True,
        "file": True,
        "sparrow7": True,
        "heron_gr1": True,
        "twin_torso": True,
    }
    rover = seen["finch_rover"]
    assert rover["type"] == "HYBRID_MOBILE_BASE"
    assert rover["body_parts"]["right"] == seen["panda_right"]
    assert rover["body_parts"]["base"] == seen["rover_base"]
    assert seen["in_lift"] == "JointPositionController"


BRIDGE_MODULES = sorted(
    module.name
    for module in pkgutil.iter_modules([str(Path(assembler.robosuite.__file__).parent)])
    if module.name not in ("__main__", "pytest_plugin")
)
"""Every module of the bridge package (``__main__`` runs a command; the plugin is pytest's)."""


@pytest.mark.parametrize("module", BRIDGE_MODULES)
def test_any_module_of_the_bridge_imported_first_leaves_our_specs_in_robosuite(
    module: str, tmp_path: Path
) -> None:
    seen = _result(
        f"""
        import json
        import assembler.robosuite.{module}
        import assembler.robosuite, robosuite
        print("RESULT " + json.dumps("Sparrow7" in assembler.robosuite.registered()["robot"]))
        """,
        tmp_path,
    )
    assert seen is True
