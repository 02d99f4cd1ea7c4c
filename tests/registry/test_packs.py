"""Spec packs: a distribution with a ``robot_assembler.specs`` entry point, built as a wheel and
installed beside the project, adds its robots to every lookup; two packs of one name are an error
naming both."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

pytestmark = pytest.mark.wheel


def _pack(folder: Path, distribution: str, robot: str) -> Path:
    """A pack's source tree: one arm (Sparrow7's spec and MJCF, renamed), its MJCF named by
    package://, an entry point naming the specs folder; built into a wheel."""
    package = distribution.replace("-", "_")
    source = folder / distribution
    specs, assets = source / package / "specs", source / package / "assets" / "arm"
    specs.mkdir(parents=True)
    shutil.copytree(ROOT / "assets" / "sparrow7", assets)
    (source / package / "__init__.py").write_text("")
    spec = (ROOT / "specs" / "sparrow7.yaml").read_text()
    spec = spec.replace("name: Sparrow7\n", f"name: {robot}\n")
    spec = spec.replace("mjcf: ../assets/sparrow7/", f"mjcf: package://{package}/assets/arm/")
    (specs / "arm.yaml").write_text(spec)
    (source / "pyproject.toml").write_text(
        '[build-system]\nrequires = ["hatchling>=1.21"]\nbuild-backend = "hatchling.build"\n\n'
        f'[project]\nname = "{distribution}"\nversion = "1.0"\n\n'
        f'[project.entry-points."robot_assembler.specs"]\n{package} = "{package}:specs"\n\n'
        f'[tool.hatch.build.targets.wheel]\npackages = ["{package}"]\n'
    )
    built = subprocess.run(
        [sys.executable, "-m", "build", "--wheel", "--outdir", str(folder / "dist"), str(source)],
        capture_output=True,
        text=True,
    )
    assert built.returncode == 0, built.stderr
    (wheel,) = (folder / "dist").glob(f"{package}-*.whl")
    return wheel


def _install(wheels: list[Path], target: Path) -> dict[str, str]:
    """The wheels installed (by pip, with their metadata) into ``target``; the environment that puts
    it beside the project."""
    for wheel in wheels:
        done = subprocess.run(
            [
                sys.executable,
                "-m",
                "pip",
                "install",
                "--quiet",
                "--no-deps",
                "--target",
                str(target),
                str(wheel),
            ],
            capture_output=True,
            text=True,
        )
        assert done.returncode == 0, done.stderr
    return {**os.environ, "PYTHONPATH": str(target), "MUJOCO_GL": "egl"}


def _assembler(env: dict[str, str], cwd: Path, *argv: str) -> subprocess.CompletedProcess[str]:
    code = "import sys; from assembler.cli import run; sys.exit(run())"
    return subprocess.run(
        [sys.executable, "-c", code, *argv], cwd=cwd, env=env, capture_output=True, text=True
    )


def test_a_pack_installed_beside_the_project_adds_its_robot_to_list_build_and_robosuite(
    tmp_path: Path,
) -> None:
    env = _install([_pack(tmp_path, "acme-robots", "AcmeArm")], tmp_path / "site")
    listed = _assembler(env, tmp_path, "list", "robots")
    assert listed.returncode == 0, listed.stderr
    (row,) = [line for line in listed.stdout.splitlines() if line.startswith("AcmeArm ")]
    assert row.split()[1:] == ["manipulator", "7", "acme_robots:arm.yaml", "(pack", "acme-robots", "1.0)"]
    built = _assembler(env, tmp_path, "build", "AcmeArm", "-o", "acme.xml")
    assert (built.returncode, built.stderr) == (0, "wrote acme.xml\n")
    import mujoco

    model = mujoco.MjModel.from_xml_path(str(tmp_path / "acme.xml"))
    reference = mujoco.MjModel.from_xml_string(_assembler(env, tmp_path, "build", "Sparrow7").stdout)
    assert (model.nbody, model.njnt, model.nu) == (reference.nbody, reference.njnt, reference.nu)
    pytest.importorskip("robosuite")
    lift = (
        "import numpy as np, assembler.robosuite, robosuite\n"
        "env = robosuite.make('Lift', robots='AcmeArm', has_renderer=False, has_offscreen_renderer=False,"
        " use_camera_obs=False)\n"
        "env.reset()\n"
        "for _ in range(5): env.step(np.zeros(env.action_dim))\n"
        "print(type(env.robots[0].robot_model).__name__, env.action_dim)\n"
    )
    ran = subprocess.run([sys.executable, "-c", lift], cwd=tmp_path, env=env, capture_output=True, text=True)
    assert ran.returncode == 0, ran.stderr
    assert ran.stdout.split() == ["AcmeArm", "7"]


def test_two_packs_of_one_name_are_an_error_naming_both_and_a_broken_entry_point_is_said(
    tmp_path: Path,
) -> None:
    wheels = [_pack(tmp_path, "acme-robots", "SharedArm"), _pack(tmp_path, "beta-robots", "SharedArm")]
    env = _install(wheels, tmp_path / "site")
    site = tmp_path / "site"
    built = _assembler(env, tmp_path, "build", "SharedArm", "-o", "x.xml")
    assert built.returncode == 1 and not (tmp_path / "x.xml").exists()
    assert built.stderr == (
        "robot 'SharedArm' is defined by pack acme-robots 1.0 (acme_robots): site/acme_robots/specs/arm.yaml "
        "and by pack beta-robots 1.0 (beta_robots): site/beta_robots/specs/arm.yaml; "
        "uninstall one of them, or ask its authors to rename theirs\n"
    )
    points = next(site.glob("beta_robots-*.dist-info")) / "entry_points.txt"
    points.write_text("[robot_assembler.specs]\nbeta_robots = beta_robots:nowhere\n")
    built = _assembler(env, tmp_path, "build", "SharedArm", "-o", "x.xml")
    assert (built.returncode, built.stderr.splitlines()[-1]) == (0, "wrote x.xml")
    assert built.stderr.splitlines()[0] == (
        "warning: spec pack beta_robots (beta-robots 1.0): 'beta_robots:nowhere' names no folder of an "
        "importable package; its robots are not available (reinstall it, or fix its entry point)"
    )


def test_new_writes_a_pack_that_installs_and_builds_its_robot_by_name(tmp_path: Path) -> None:
    vendor = tmp_path / "vendor"
    vendor.mkdir()
    shutil.copy(ROOT / "assets" / "sparrow7" / "sparrow7.xml", vendor / "arm.xml")
    (vendor / "LICENSE").write_text("The vendor's licence.\n")
    before = {path.name: path.read_bytes() for path in vendor.iterdir()}
    wrote = _assembler(dict(os.environ), tmp_path, "new", "vendor/arm.xml", "--pack", "lab-robots")
    assert wrote.returncode == 0, wrote.stderr
    assert wrote.stdout.splitlines()[0].startswith(
        "wrote lab-robots/lab_robots/specs/sparrow7_arm.yaml: robot Sparrow7Arm, and 2 vendor files under "
        "lab-robots/lab_robots/assets and lab-robots/pyproject.toml (validated and compiled)"
    )
    spec = tmp_path / "lab-robots" / "lab_robots" / "specs" / "sparrow7_arm.yaml"
    assert {
        path.name: path.read_bytes() for path in vendor.iterdir()
    } == before  # the vendor's files untouched
    copied = tmp_path / "lab-robots" / "lab_robots" / "assets" / "arm"
    assert (copied / "arm.xml").read_bytes() == before["arm.xml"]
    assert (copied / "LICENSE").read_bytes() == before["LICENSE"]
    assert "mjcf: package://lab_robots/assets/arm/arm.xml" in spec.read_text()
    built = subprocess.run(
        [
            sys.executable,
            "-m",
            "build",
            "--wheel",
            "--outdir",
            str(tmp_path / "dist"),
            str(tmp_path / "lab-robots"),
        ],
        capture_output=True,
        text=True,
    )
    assert built.returncode == 0, built.stderr
    env = _install(list((tmp_path / "dist").glob("lab_robots-*.whl")), tmp_path / "site")
    work = tmp_path / "elsewhere"
    work.mkdir()
    done = _assembler(env, work, "build", "Sparrow7Arm", "-o", "robot.xml")
    assert (done.returncode, done.stderr) == (0, "wrote robot.xml\n")
