"""The examples of the README and of the pages its examples moved to work: their Python runs,
their specs validate, the public names exist. Each page's examples are tested like the README's."""

from __future__ import annotations

import re
import subprocess
import sys
from pathlib import Path

import pytest

import assembler
from assembler.files.repositories import find_repository
from assembler.registry.catalog import PARENTS
from assembler.spec.spec_files import load_string

ROOT = Path(__file__).parent.parent
README = ROOT / "README.md"
GETTING_STARTED = ROOT / "docs" / "getting-started.md"
URDF_PAGE = ROOT / "docs" / "urdf.md"
GPU_PAGE = ROOT / "docs" / "gpu.md"

EXAMPLE_PAGES = (README, GETTING_STARTED, GPU_PAGE)
"""The pages whose Python examples run here: the README, the tutorial it leads to, and the engines'
page (its examples run where the engine is installed)."""


def _blocks(language: str, *pages: Path) -> list[str]:
    """The code blocks of ``language`` in ``pages`` (all of EXAMPLE_PAGES by default), in order."""
    texts = [page.read_text() for page in pages or EXAMPLE_PAGES]
    return [
        block for text in texts for block in re.findall(rf"```{language}\n(.*?)```", text, flags=re.DOTALL)
    ]


ROBOSUITE_IMPORT = "import assembler.robosuite"
"""Examples with this line run in robosuite, in a process of their own (the import registers with
robosuite's tables for the whole process)."""


ENGINE_IMPORTS = {"from assembler.warp import": "mujoco_warp", "from assembler.mjlab import": "mjlab"}
"""Examples with one of these lines need that engine (an extra): they run, each in a process of its
own, where the engine is installed (CI's warp and mjlab stages)."""


def _needs_an_engine(example: str) -> bool:
    return any(line in example for line in ENGINE_IMPORTS)


@pytest.mark.parametrize("page", EXAMPLE_PAGES, ids=lambda p: p.name)
def test_readme_python_examples_run(page: Path) -> None:
    for example in _blocks("python", page):
        if ROBOSUITE_IMPORT not in example and not _needs_an_engine(example):
            exec(compile(example, page.name, "exec"), {})


def test_the_readme_and_getting_started_have_python_examples_that_run_here() -> None:
    for page in (README, GETTING_STARTED):
        runnable = [
            b for b in _blocks("python", page) if ROBOSUITE_IMPORT not in b and not _needs_an_engine(b)
        ]
        assert runnable, f"{page.name} has no Python example that runs without robosuite or an engine"


@pytest.mark.parametrize(("line", "engine"), sorted(ENGINE_IMPORTS.items()))
def test_readme_engine_examples_print_what_they_say(line: str, engine: str, tmp_path: Path) -> None:
    pytest.importorskip(engine, reason=f"needs {engine}: pip install -e '.[warp]' or '.[mjlab]'")
    examples = [block for block in _blocks("python") if line in block]
    assert examples, f"no page of {[p.name for p in EXAMPLE_PAGES]} has an example with '{line}'"
    for example in examples:
        run = subprocess.run(
            [sys.executable, "-c", example], cwd=tmp_path, capture_output=True, text=True, timeout=1800
        )
        assert run.returncode == 0, run.stderr[-3000:]
        printed = run.stdout.splitlines()[-1]
        assert "print(" in example and f"# {printed}" in example  # what the page says it prints


def test_readme_robosuite_example_runs_a_spec_robot_in_robosuites_lift(tmp_path: Path) -> None:
    pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[robosuite]"')
    (example,) = [block for block in _blocks("python") if ROBOSUITE_IMPORT in block]
    run = subprocess.run(
        [sys.executable, "-c", example], cwd=tmp_path, capture_output=True, text=True, timeout=600
    )
    assert run.returncode == 0, run.stderr
    printed = run.stdout.splitlines()[-1]
    assert printed == "assembler.robosuite.robot_class 7"
    assert f"# {printed}" in example  # what the page says it prints


def test_readme_spec_example_validates(monkeypatch: pytest.MonkeyPatch) -> None:
    (spec_text,) = _blocks("yaml", README)
    monkeypatch.chdir(ROOT / "specs")  # its mjcf path is relative to specs/, where a user would save it
    loaded = load_string(spec_text, PARENTS)
    assert loaded.spec.name == "Sparrow7Soft"
    assert loaded.spec.resolve_base_xpos_offset("table", table_length=0.8)[0] == -0.56


def test_readme_spec_example_builds_a_robot() -> None:
    (spec_text,) = _blocks("yaml", README)
    # the example's mjcf path is relative to specs/, where a user would save it
    text = spec_text.replace(
        "../assets/sparrow7/sparrow7.xml", str(ROOT / "assets" / "sparrow7" / "sparrow7.xml")
    )
    robot = assembler.register_spec_string(text)(idn=0)
    assert robot.joint_values["joint6"]["frictionloss"].value == 0.02
    assert str(robot.joint_values["joint6"]["damping"].source) == "mjcf (class 'wrist')"


def test_readme_urdf_example_validates() -> None:
    (urdf_text,) = _blocks("yaml", URDF_PAGE)
    spec = load_string(urdf_text, PARENTS).spec
    assert spec.urdf == "package://example-robot-data/robots/so_arm_description/urdf/so101.urdf"
    assert spec.actuators[0].kp == 50 and spec.actuators[0].forcerange == (-3.5, 3.5)


def test_readme_commands_are_the_documented_install_and_test_commands() -> None:
    commands = _blocks("bash", README)
    assert commands == [  # exactly two commands for a fresh machine: the main job, the tests
        "pip install . && assembler build Sparrow7 -o sparrow7.xml\n",
        'pip install -e ".[test,robosuite,urdf]" && pytest\n',
    ]
    assert _blocks("bash", GETTING_STARTED) == ['pip install ".[robosuite]"\n']  # with an extra
    assert 'pip install -e ".[test,robosuite,urdf]" && pytest' in (ROOT / ".ci" / "run").read_text()


def test_public_api_names_exist() -> None:
    missing = [name for name in assembler.__all__ if not hasattr(assembler, name)]
    assert missing == []


def test_readme_spec_repository_table_is_what_the_loader_reads(tmp_path: Path) -> None:
    (table,) = _blocks("toml", README, GETTING_STARTED)
    for folder in ("specs", "assets", "meshes"):
        (tmp_path / folder).mkdir()
    (tmp_path / "pyproject.toml").write_text(table)
    repository = find_repository(tmp_path / "specs")
    assert repository is not None and repository.root == tmp_path.resolve()
    assert [p.name for p in repository.readable] == ["specs", "assets", "meshes"]
