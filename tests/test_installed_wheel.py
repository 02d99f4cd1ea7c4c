"""The README's repository commands as a new user meets them: the built wheel installed in a fresh
environment (``pip install .``, no extras), used in a copy of this repository and in a scratch lab
repository checked by the pre-commit hooks' own commands, never from the source tree.

One fresh environment serves the module (building and installing take about half a minute,
mostly pip installing MuJoCo and numpy from its cache); each command runs as the installed
``assembler`` script, in a new process.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path

import pytest
import yaml

from assembler.files.extras import install_command

pytestmark = pytest.mark.wheel

ROOT = Path(__file__).parent.parent
README = (ROOT / "README.md").read_text()
GIT = ["git", "-c", "user.name=Test", "-c", "user.email=test@example.com", "-c", "init.defaultBranch=main"]

URDF_MISSING = (
    "    because: package 'example-robot-data' not found (searched ROS_PACKAGE_PATH, AMENT_PREFIX_PATH "
    f"and the share/ folders of this Python environment); install it: {install_command('urdf')}"
)


def _own_specs(clone: Path) -> list[Path]:
    """The clone's part specs that read no other package's files (not robosuite's, not the URDF ones;
    motor specs are counted on a line of their own)."""
    return [
        p for p in (clone / "specs").rglob("*.yaml") if not {"robosuite", "urdf", "motors"} & set(p.parts)
    ]


ROBOSUITE_MISSING = (
    "    because: Python package 'robosuite' is not installed; install it with pip install "
    'robosuite==1.5.2 (the robosuite extra; in a clone: pip install ".[robosuite]")'
)

BLOCKY_MJCF = """\
<mujoco model="blocky">
  <compiler angle="radian"/>
  <worldbody>
    <body name="base">
      <geom name="base_col" type="box" size="0.1 0.1 0.05" mass="5"/>
      <geom name="base_vis" type="box" size="0.1 0.1 0.05" group="1" contype="0" conaffinity="0" mass="0"/>
      <site name="right_center" pos="0 0 0.1"/>
      <body name="link1" pos="0 0 0.1">
        <joint name="joint1" axis="0 0 1" range="-3 3"/>
        <geom name="link1_col" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" mass="1"/>
        <geom name="link1_vis" type="capsule" fromto="0 0 0 0.3 0 0" size="0.03" group="1"
              contype="0" conaffinity="0" mass="0"/>
        <body name="right_hand" pos="0.3 0 0"/>
      </body>
    </body>
  </worldbody>
  <actuator>
    <motor name="act1" joint="joint1" ctrlrange="-20 20"/>
  </actuator>
</mujoco>
"""
"""A new robot, as "Adding a robot" has one added: one root body, named joints, visual geoms in group 1,
the arm's center site and motors (what robosuite's controllers drive)."""


@dataclass(frozen=True)
class Installed:
    """A fresh environment with the wheel installed, and where to work."""

    bin: Path
    scratch: Path

    def run(self, folder: Path, *argv: str) -> subprocess.CompletedProcess[str]:
        """``argv`` (``assembler ...`` or another script of the environment) run in ``folder``."""
        env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "ASSEMBLER_ALLOW_PATHS")}
        env["PATH"] = f"{self.bin}{os.pathsep}{env.get('PATH', '')}"
        env["VIRTUAL_ENV"] = str(self.bin.parent)
        return subprocess.run(
            [str(self.bin / argv[0]), *argv[1:]], cwd=folder, capture_output=True, text=True, env=env
        )

    def ok(self, folder: Path, *argv: str, err: str = "") -> list[str]:
        """The lines a command printed on standard output; it must succeed and print ``err`` on
        standard error (nothing, unless told)."""
        done = self.run(folder, *argv)
        assert (done.returncode, done.stderr) == (0, err), f"{argv}: {done.stderr}"
        return done.stdout.splitlines()


def _pip(python: Path, *argv: str) -> None:
    done = subprocess.run([str(python), "-m", "pip", *argv], capture_output=True, text=True)
    assert done.returncode == 0, done.stderr


@pytest.fixture(scope="module")
def installed(tmp_path_factory: pytest.TempPathFactory) -> Installed:
    """Build the wheel from this checkout and install it into a new environment, as ``pip install .``."""
    base = tmp_path_factory.mktemp("wheel")
    build = [sys.executable, "-m", "build", "--wheel", "--outdir", str(base / "dist"), str(ROOT)]
    done = subprocess.run(build, capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    (wheel,) = (base / "dist").glob("robot_assembler-*.whl")
    subprocess.run([sys.executable, "-m", "venv", str(base / "venv")], check=True)
    _pip(base / "venv" / "bin" / "python", "install", "--quiet", str(wheel))
    scratch = base / "scratch"
    scratch.mkdir()
    return Installed(base / "venv" / "bin", scratch)


def _copy_of_this_repository(target: Path) -> Path:
    """This checkout's files (committed or not, ignored ones left out) in a new git repository."""
    listed = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=ROOT,
        capture_output=True,
        check=True,
    )
    for name in filter(None, listed.stdout.decode().split("\0")):
        source = ROOT / name
        if source.is_file():
            (target / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(source, target / name)
    _commit(target, "the repository as cloned")
    return target


def _commit(folder: Path, message: str) -> None:
    if not (folder / ".git").exists():
        subprocess.run([*GIT, "init", "-q"], cwd=folder, check=True)
    subprocess.run([*GIT, "add", "-A"], cwd=folder, check=True)
    subprocess.run([*GIT, "commit", "-q", "-m", message], cwd=folder, check=True)


@pytest.fixture(scope="module")
def clone(installed: Installed) -> Path:
    return _copy_of_this_repository(installed.scratch / "clone")


def _readme_command(command: str) -> list[str]:
    """A command the README shows (``$ assembler ...``), split, with its trailing comment removed."""
    assert command.removeprefix("assembler ") in README, f"the README no longer shows {command}"
    return command.split()


def test_the_wheel_is_what_runs_not_the_source_tree(installed: Installed) -> None:
    code = "import assembler, assembler.files.paths as p; print(assembler.__file__); print(p.shipped_specs_dir())"
    module, specs = installed.ok(installed.scratch, "python", "-c", code)
    assert "site-packages" in module and specs.endswith("site-packages/assembler/_shipped/specs")


def test_list_and_build_work_outside_any_checkout(installed: Installed) -> None:
    rows = [line.split() for line in installed.ok(installed.scratch, "assembler", "list")[1:]]
    assert ["Sparrow7", "manipulator", "7", "specs/sparrow7.yaml", "(shipped)"] in rows
    assert [row[0] for row in rows] == sorted((row[0] for row in rows), key=str.casefold)
    build = ("assembler", "build", "Sparrow7", "-o", "sparrow7.xml")
    assert installed.ok(installed.scratch, *build, err="wrote sparrow7.xml\n") == []
    check = "import mujoco; print(mujoco.MjModel.from_xml_path('sparrow7.xml').nq)"
    assert installed.ok(installed.scratch, "python", "-c", check) == ["9"]  # 7 arm joints, 2 fingers


def test_validate_specs_compile_in_the_clone_counts_what_it_compiled(
    installed: Installed, clone: Path
) -> None:
    own = _own_specs(clone)
    robosuite = list((clone / "specs" / "robosuite").rglob("*.yaml"))
    urdf = list((clone / "specs" / "urdf").rglob("*.yaml"))
    motors = list((clone / "specs" / "motors").rglob("*.yaml"))
    lines = installed.ok(clone, *_readme_command("assembler validate specs/ --compile"))
    motor_line = lines.pop()
    assert motor_line.startswith(f"{len(motors)} motor spec(s) valid: ") and len(motors) >= 12
    compiled, *unchecked = lines
    assert compiled.startswith(f"{len(own)} spec(s) validated and compiled: Pedestal, QuadrupedBase, ")
    # one pair of lines per package not installed in the fresh environment: robosuite, the urdf extra
    reasons = dict(zip(unchecked[1::2], unchecked[::2], strict=True))
    assert reasons[ROBOSUITE_MISSING].startswith(
        f"{len(robosuite)} spec(s) valid but not checked against their model file nor compiled: "
    )
    assert reasons[URDF_MISSING].startswith(
        f"{len(urdf)} spec(s) valid but not checked against their model file nor compiled: "
    )
    assert installed.ok(clone, "assembler", "validate", "scenes/", "experiments/") == [
        "2 scene and experiment file(s) valid: scenes/two_arms.yaml, experiments/soft_pair.yaml"
    ]


def test_list_in_the_clone_shows_short_paths(installed: Installed, clone: Path) -> None:
    rows = [line.split() for line in installed.ok(clone, "assembler", "list", "bases")[1:]]
    assert ["Pedestal", "mount", "0", "specs/bases/pedestal.yaml", "(shipped)"] in rows


def test_the_spec_format_example_saved_under_specs_validates_and_builds(
    installed: Installed, clone: Path
) -> None:
    example = re.findall(r"```yaml\n(.*?)```", README, flags=re.DOTALL)[0]  # the spec format's
    (clone / "specs" / "sparrow7_soft.yaml").write_text(example)
    assert installed.ok(clone, "assembler", "validate", "specs/sparrow7_soft.yaml", "--compile") == [
        "1 spec(s) validated and compiled: Sparrow7Soft"
    ]
    build = ("assembler", "build", "specs/sparrow7_soft.yaml", "-o", "soft.xml")
    assert installed.ok(clone, *build, err="wrote soft.xml\n") == []
    (clone / "specs" / "sparrow7_soft.yaml").unlink()


def test_adding_a_robot_as_the_readme_says(installed: Installed, clone: Path) -> None:
    # 1. the MJCF in assets/<robot>/; 2. specs/<robot>.yaml with name and mjcf; 3. validate.
    (clone / "assets" / "blocky").mkdir()
    (clone / "assets" / "blocky" / "blocky.xml").write_text(BLOCKY_MJCF)
    (clone / "specs" / "blocky.yaml").write_text("name: Blocky\nmjcf: ../assets/blocky/blocky.xml\n")
    try:
        compiled = installed.ok(clone, "assembler", "validate", "specs/", "--compile")[0]
        count, names = compiled.split(" spec(s) validated and compiled: ")
        own = _own_specs(clone)
        assert int(count) == len(own) and "Blocky" in names.split(", ")
        assert installed.ok(clone, "assembler", "lint", "specs/blocky.yaml") == ["Blocky: no findings"]
    finally:
        shutil.rmtree(clone / "assets" / "blocky")
        (clone / "specs" / "blocky.yaml").unlink()


def test_diff_a_committed_change_against_its_parent_commit(installed: Installed, clone: Path) -> None:
    spec = clone / "specs" / "sparrow7.yaml"
    original = spec.read_text()
    spec.write_text(original.replace("  damping: 0.1\n", "  damping: 0.3\n", 1))
    _commit(clone, "softer Sparrow7")
    try:
        command = _readme_command("assembler diff specs/sparrow7.yaml@HEAD~1 specs/sparrow7.yaml")
        lines = installed.ok(clone, *command)
        assert "spec fields (1 changed)" in lines
        assert any(re.fullmatch(r"  joint_defaults\.damping +0\.1 -> 0\.3", line) for line in lines)
        assert any(re.fullmatch(r"  joint +robot0_joint1 +damping +0\.1 -> 0\.3", line) for line in lines)
        # the edited copy is no longer the installed Sparrow7: two specs of one name, both named
        done = installed.run(clone, "assembler", "validate", "specs/sparrow7.yaml")
        (line,) = done.stderr.splitlines()
        assert done.returncode == 1 and line.startswith("specs/sparrow7.yaml:4:7: name: robot 'Sparrow7' is ")
        assert re.search(
            r"already registered by /\S+/site-packages/assembler/_shipped/specs/sparrow7\.yaml", line
        )
        assert line.endswith(
            'install the clone with pip install -e ".[robosuite]"), a different spec; rename one'
        )
    finally:
        spec.write_text(original)
        _commit(clone, "Sparrow7 as shipped")


# ----- a lab's own robot repository, checked by our pre-commit hooks ------------------------------

LAB_SOFT = "name: BlockySoft\nextends: blocky.yaml\njoint_defaults: {damping: 0.5}\n"


def _lab(folder: Path, declared: bool) -> Path:
    (folder / "assets" / "blocky").mkdir(parents=True)
    (folder / "assets" / "blocky" / "blocky.xml").write_text(BLOCKY_MJCF)
    (folder / "specs").mkdir()
    (folder / "specs" / "blocky.yaml").write_text("name: Blocky\nmjcf: ../assets/blocky/blocky.xml\n")
    (folder / "specs" / "blocky_soft.yaml").write_text(LAB_SOFT)
    (folder / "README.md").write_text("Our robots.\n")
    if declared:
        (folder / "robot-assembler.toml").write_text("")
    _commit(folder, "our robots")
    return folder


def _run_hooks(installed: Installed, repository: Path) -> list[subprocess.CompletedProcess[str]]:
    """Each hook of .pre-commit-hooks.yaml as pre-commit runs it: its entry, from the repository's
    root, with every tracked file its ``files`` pattern matches, all in one call."""
    hooks = yaml.safe_load((ROOT / ".pre-commit-hooks.yaml").read_text())
    tracked = subprocess.run(["git", "ls-files"], cwd=repository, capture_output=True, text=True, check=True)
    results = []
    for hook in hooks:
        if "files" not in hook:  # assembler-locked: opt-in, for a repository that keeps a lock
            continue
        files = [name for name in tracked.stdout.splitlines() if re.search(hook["files"], name)]
        assert files == ["specs/blocky.yaml", "specs/blocky_soft.yaml"], hook["id"]
        results.append(installed.run(repository, *hook["entry"].split(), *files))
    return results


def test_a_declared_lab_repository_passes_the_pre_commit_hooks(installed: Installed) -> None:
    lab = _lab(installed.scratch / "lab", declared=True)
    validate, lint = _run_hooks(installed, lab)
    assert (validate.returncode, validate.stderr) == (0, "")
    assert validate.stdout == "2 spec(s) validated and compiled: Blocky, BlockySoft\n"
    assert (lint.returncode, lint.stderr) == (0, "")
    assert lint.stdout == "Blocky: no findings\nBlockySoft: no findings\n"


def test_an_undeclared_lab_repository_is_told_how_to_declare_itself(installed: Installed) -> None:
    lab = _lab(installed.scratch / "undeclared", declared=False)
    validate, _ = _run_hooks(installed, lab)
    assert validate.returncode == 1
    assert validate.stderr.splitlines()[0] == (
        "specs/blocky.yaml:2:7: mjcf: assets/blocky/blocky.xml is outside the folders a spec may read "
        "(its own folder, the shipped specs and assets, installed packages); pass --allow-path DIR (or set "
        f"ASSEMBLER_ALLOW_PATHS) to allow it, or declare the checkout {lab.resolve()} a spec repository "
        "(an empty robot-assembler.toml at its root lets its specs read its specs/ and assets/ folders; "
        "README: Spec repositories)"
    )
