"""The start-up hook's ``.pth`` line is harmless: it imports no package into an unrelated process, and
once robot-assembler is uninstalled it does nothing (or, with robosuite, says so in one line).

Each case is a scratch virtual environment holding only the hook's ``.pth`` file, whose line points at
a copy of ``hook.py`` (the installed file, as ``--install-hook`` writes it); removing the copy is what
``pip uninstall`` does to the package's files, while the ``.pth`` file, written by us, stays.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

from assembler.robosuite import hook

VARIABLE = {"ASSEMBLER_ROBOSUITE_SPECS": "my_robots"}


def _scratch_venv(root: Path) -> tuple[str, Path]:
    """A venv without pip or this project, with the hook's .pth line pointing at a copy of hook.py."""
    venv = root / "venv"
    subprocess.run([sys.executable, "-m", "venv", "--without-pip", str(venv)], check=True)
    python = str(venv / "bin" / "python")
    site = subprocess.run(
        [python, "-c", "import sysconfig; print(sysconfig.get_paths()['purelib'])"],
        capture_output=True,
        text=True,
        check=True,
    ).stdout.strip()
    installed = root / "installed" / "hook.py"
    installed.parent.mkdir()
    shutil.copy(hook.__file__, installed)
    (Path(site) / "assembler-robosuite.pth").write_text(hook.pth_line(str(installed)))
    return python, installed


def _run(python: str, code: str, **variables: str) -> subprocess.CompletedProcess[str]:
    """``python -c code`` outside this checkout (``-c`` puts the working folder on the path)."""
    environment = {
        key: value
        for key, value in os.environ.items()
        if key not in ("PYTHONPATH", *hook.VARIABLES) and not key.startswith("PYTEST")
    }
    return subprocess.run(
        [python, "-c", code],
        env={**environment, **variables},
        cwd=Path(python).parents[2],
        capture_output=True,
        text=True,
        check=False,
    )


def test_with_the_variable_set_the_hook_imports_no_package_into_an_unrelated_process(tmp_path: Path) -> None:
    python, _ = _scratch_venv(tmp_path)
    code = "import sys; print(sorted(sys.modules)); print([type(f).__name__ for f in sys.meta_path])"
    plain = _run(python, code)
    hooked = _run(python, code, **VARIABLE)
    assert hooked.returncode == 0 and hooked.stderr == ""
    modules = set(eval(hooked.stdout.splitlines()[0])) - set(eval(plain.stdout.splitlines()[0]))
    assert not {name for name in modules if name.startswith(("assembler", "robosuite", "mujoco", "numpy"))}
    assert "AfterRobosuite" in hooked.stdout.splitlines()[1]


def test_after_the_package_is_uninstalled_the_hooks_line_does_nothing_and_says_nothing(
    tmp_path: Path,
) -> None:
    python, installed = _scratch_venv(tmp_path)
    installed.unlink()
    done = _run(python, "print('ran')", **VARIABLE)
    assert (done.returncode, done.stdout, done.stderr) == (0, "ran\n", "")


def test_robosuite_still_imports_where_the_hook_outlived_the_package_and_it_says_so_once(
    tmp_path: Path,
) -> None:
    pytest.importorskip("robosuite", reason='needs robosuite: pip install ".[test,robosuite]"')
    python, installed = _scratch_venv(tmp_path)
    # robosuite and its dependencies from this interpreter's site-packages, whose .pth files (among
    # them the one that makes this checkout importable) a PYTHONPATH folder does not run
    packages = sysconfig.get_paths()["purelib"]
    done = _run(
        python, "import robosuite; print('imported')", PYTHONPATH=packages, MUJOCO_GL="egl", **VARIABLE
    )
    assert done.returncode == 0, done.stderr[-3000:]
    assert done.stdout.splitlines()[-1] == "imported"
    said = [line for line in done.stderr.splitlines() if line.startswith("assembler")]
    assert said == [
        f"assembler.robosuite: the start-up hook {installed} runs, but the package is not installed here; "
        "remove the hook's .pth file or reinstall robot-assembler"
    ]


def test_python_m_without_robosuite_says_what_to_install_in_one_line(tmp_path: Path) -> None:
    python, _ = _scratch_venv(tmp_path)
    packages = tmp_path / "packages"  # this interpreter's packages but robosuite, linked
    packages.mkdir()
    for entry in Path(sysconfig.get_paths()["purelib"]).iterdir():
        if not entry.name.startswith("robosuite") and entry.suffix != ".pth":
            os.symlink(entry, packages / entry.name)
    checkout = Path(hook.__file__).resolve().parents[2]
    done = _run(
        python,
        "import runpy; runpy.run_module('assembler.robosuite', run_name='__main__')",
        PYTHONPATH=f"{checkout}{os.pathsep}{packages}",
    )
    assert done.returncode == 2 and "Traceback" not in done.stderr  # no argument: the usage, as before
    for argv in (["--check"], ["train.py"]):
        code = f"import sys, runpy; sys.argv = ['x', *{argv!r}]; runpy.run_module('assembler.robosuite', run_name='__main__')"
        done = _run(python, code, PYTHONPATH=f"{checkout}{os.pathsep}{packages}")
        assert done.returncode == 1, done.stderr[-2000:]
        assert done.stderr.splitlines() == [
            "assembler.robosuite needs robosuite (No module named 'robosuite'); "
            "install it with: pip install -e '.[robosuite]'"
        ]
