"""Every way a command can end badly ends with at most one line per problem and the right exit code,
never a traceback: closed pipes, full disks, Ctrl-C, impossible paths, cycles of extends at any
depth, NUL characters in paths. Commands run in new processes, as a user runs them."""

from __future__ import annotations

import ctypes.util
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from assembler.cli import main
from assembler.files.paths import package_root
from tests.conftest import TWO_LINK_MJCF

CLI = "import sys; from assembler.cli import run; sys.exit(run())"
"""The ``assembler`` command, run by this Python in a new process."""


def _run(*argv: str, cwd: Path, stdout: int | None = subprocess.PIPE) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-c", CLI, *argv], cwd=cwd, stdout=stdout, stderr=subprocess.PIPE, text=True
    )


def test_a_closed_pipe_ends_silently_with_141(tmp_path: Path) -> None:
    # `assembler list | head -0`: the reader is gone before the command writes anything.
    reader, writer = os.pipe()
    os.close(reader)
    command = subprocess.Popen(
        [sys.executable, "-c", CLI, "list", "bases"], stdout=writer, stderr=subprocess.PIPE, text=True
    )
    os.close(writer)
    _, err = command.communicate(timeout=120)
    assert (command.returncode, err) == (141, "")


def test_a_full_standard_output_is_one_line(tmp_path: Path) -> None:
    with open("/dev/full", "w") as full:
        done = subprocess.run(
            [sys.executable, "-c", CLI, "build", "Sparrow7"], stdout=full, stderr=subprocess.PIPE, text=True
        )
    assert (done.returncode, done.stderr) == (1, "cannot write to standard output: No space left on device\n")


def _mapped(pid: int, library: str) -> bool:
    """True once process ``pid`` has loaded a shared library whose name contains ``library``."""
    try:
        return library in Path(f"/proc/{pid}/maps").read_text()
    except OSError:
        return False


@pytest.mark.skipif(not Path("/proc/self/maps").exists(), reason="needs /proc to see the command's progress")
@pytest.mark.parametrize("moment", ["while it imports MuJoCo", "while it builds"])
def test_ctrl_c_is_one_line_and_130(moment: str, tmp_path: Path) -> None:
    # Long enough to be inside the build after 3 s: GR1's meshes, or many variants of our own Biped.
    robot, count = ("GR1", 4) if package_root("robosuite") else ("Biped", 400)
    # A description per variant: not a patchable field, so every variant is compiled and the run is
    # still building when it is interrupted (a patchable grid is written in milliseconds per variant).
    values = ",".join(f"run{index}" for index in range(count))
    command = subprocess.Popen(
        [sys.executable, "-c", CLI, "variants", robot, "--grid", f"description={values}"]
        + ["--no-cache", "--jobs", "1", "-o", "out"],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        text=True,
    )
    deadline = time.monotonic() + 60
    while not _mapped(command.pid, "libmujoco") and time.monotonic() < deadline:
        time.sleep(0.001)
    if moment == "while it builds":
        time.sleep(3.0)  # the specs are read, GR1's meshes are being compiled
    command.send_signal(signal.SIGINT)
    _, err = command.communicate(timeout=120)
    assert (command.returncode, err) == (130, "interrupted\n")
    written = list((tmp_path / "out").glob("*")) if (tmp_path / "out").exists() else []
    assert not [path for path in written if path.name.endswith(".tmp")]


def test_a_legal_long_file_name_is_written(tmp_path: Path) -> None:
    name = "a" * 246 + ".xml"  # 250 characters: legal, but not with a temporary name around it
    done = _run("build", "Sparrow7", "-o", name, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert os.listdir(tmp_path) == [name]


def test_a_path_past_the_systems_limit_is_one_short_line(tmp_path: Path) -> None:
    done = _run("build", "Sparrow7", "-o", "d/" * 2100 + "x.xml", cwd=tmp_path)
    (line,) = done.stderr.splitlines()
    assert done.returncode == 1 and line.endswith(": File name too long")
    assert "...(4205 characters)..." in line and len(line) < 300


def test_variants_into_a_folder_that_cannot_exist_is_one_line(tmp_path: Path) -> None:
    done = _run(
        "variants", "Sparrow7", "--grid", "joint_defaults.damping=0.1,0.2", "-o", "/proc/no", cwd=tmp_path
    )
    assert (done.returncode, done.stderr) == (1, "cannot write /proc/no: No such file or directory\n")


def _chain(folder: Path, length: int, back_to: int | None) -> Path:
    """Spec files c0 -> c1 -> ... -> c{length-1}, the last extending c{back_to} (or nothing)."""
    folder.mkdir()
    (folder / "twolink.xml").write_text(TWO_LINK_MJCF)
    for index in range(length):
        text = f"name: C{index}\n" + ("mjcf: twolink.xml\n" if index == 0 else "")
        if index < length - 1:
            text += f"extends: c{index + 1}.yaml\n"
        elif back_to is not None:
            text += f"extends: c{back_to}.yaml\n"
        (folder / f"c{index}.yaml").write_text(text)
    return folder / "c0.yaml"


@pytest.mark.parametrize("length", [1, 2, 40])
def test_a_cycle_of_extends_through_files_is_named_once(
    length: int, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    first = _chain(tmp_path / "specs", length, back_to=0)
    assert main(["validate", str(first)]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    cycle = " -> ".join(f"C{index}" for index in sorted(range(length), key=str)) if length < 10 else ""
    assert line.endswith("; break it") and "inheritance cycle: C0 -> " in line
    if cycle:
        assert f"inheritance cycle: {cycle} -> C0; break it" in line


def test_a_chain_of_extends_deeper_than_the_limit_is_one_line(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    first = _chain(tmp_path / "specs", 300, back_to=None)
    assert main(["validate", str(first)]) == 1
    (line,) = capsys.readouterr().err.splitlines()
    assert line.endswith("extends: more than 64 levels of extends; a spec inherits from a few parents")


@pytest.mark.parametrize(
    ("field", "text"),
    [
        ("mjcf", 'name: N\nmjcf: "arm\\0.xml"\n'),
        ("extends", 'name: N\nextends: "arm\\0.yaml"\n'),
    ],
)
def test_a_nul_written_in_a_path_field_is_a_positioned_line(
    field: str, text: str, tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    spec = tmp_path / "nul.yaml"
    spec.write_text(text)
    assert main(["validate", str(spec)]) == 1
    assert capsys.readouterr().err == (
        f"{spec}:2:{len(field) + 3}: {field}: YAML: character #x0000 (written as an escape) is not allowed in "
        "text; remove it\n"
    )


def test_a_broken_cache_entry_never_writes_mujocos_log_into_the_working_folder(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("ASSEMBLER_CACHE_DIR", str(tmp_path / "cache"))
    assert _run("build", "Sparrow7", "-o", "a.xml", cwd=tmp_path).returncode == 0
    (entry,) = (tmp_path / "cache").glob("*.mjb")
    damaged = bytearray(entry.read_bytes())
    damaged[len(damaged) // 3] ^= 0xFF
    entry.write_bytes(bytes(damaged))
    done = _run("build", "Sparrow7", "-o", "b.xml", cwd=tmp_path)
    assert (done.returncode, done.stderr) == (0, "wrote b.xml\n")
    assert (tmp_path / "a.xml").read_text() == (tmp_path / "b.xml").read_text()
    assert not (tmp_path / "MUJOCO_LOG.TXT").exists()


INTERRUPTING_IMPORT = """
import importlib.abc, os, signal, sys

class Interrupt(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path, target=None):
        if name == sys.argv[1]:
            os.kill(os.getpid(), signal.SIGINT)  # Ctrl-C, as the module starts importing
        return None

sys.meta_path.insert(0, Interrupt())
from assembler.cli import main  # as the console script does
sys.exit(main(sys.argv[2:]))
"""


@pytest.mark.parametrize(
    "module",
    ["assembler.cli.arguments", "assembler.cli.endings", "assembler.files.cache_location", "mujoco"],
)
def test_ctrl_c_while_the_command_starts_is_one_line_and_130(module: str, tmp_path: Path) -> None:
    """Found by the hostile-input battery: Ctrl-C in the first ~20 ms, while the console script
    imports the CLI (before end_cleanly runs), was a traceback and a death by SIGINT (-2)."""
    done = subprocess.run(
        [sys.executable, "-c", INTERRUPTING_IMPORT, module, "build", "Sparrow7", "-o", "x.xml"],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        timeout=300,
    )
    assert (done.returncode, done.stderr) == (130, "interrupted\n")
    assert os.listdir(tmp_path) == []


def test_importing_the_cli_leaves_ctrl_c_to_the_program() -> None:
    done = subprocess.run(
        [
            sys.executable,
            "-c",
            "import signal, assembler.cli; print(signal.getsignal(signal.SIGINT).__name__)",
        ],
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert (done.returncode, done.stdout) == (0, "default_int_handler\n")


IN_A_DELETED_FOLDER = """
import os, sys
os.makedirs(sys.argv[1])
os.chdir(sys.argv[1])
os.rmdir(sys.argv[1])  # the working folder is gone, as after rm -rf of the shell's folder
if sys.argv[2] == "api":
    import assembler
    model = assembler.load_model("Sparrow7")
    print(model.njnt, assembler.assemble("Sparrow7").get_xml()[:7])
else:
    from assembler.cli import main
    sys.exit(main(sys.argv[2:]))
"""


@pytest.mark.parametrize(
    ("words", "expected"),
    [
        (["build", "Sparrow7", "-o", "{tmp}/x.xml"], "deleted"),
        (["validate", "Sparrow7"], "deleted"),
        (["api"], ""),
    ],
    ids=["build", "validate", "the-api-still-works"],
)
def test_a_deleted_working_folder_is_one_line(words: list[str], expected: str, tmp_path: Path) -> None:
    """Found by the hostile-input battery: the request's key read os.getcwd() (a traceback)."""
    script = tmp_path / "run.py"
    script.write_text(IN_A_DELETED_FOLDER)
    argv = [word.format(tmp=tmp_path) for word in words]
    for _ in range(2):  # compiled, then answered from the cache
        done = subprocess.run(
            [sys.executable, str(script), str(tmp_path / "gone"), *argv],
            capture_output=True,
            text=True,
            timeout=300,
        )
        if expected:
            assert (done.returncode, done.stderr) == (
                1,
                "the working folder cannot be read (No such file or directory): it was deleted or moved "
                "away; cd to a folder that exists and run the command again\n",
            )
        else:
            assert (done.returncode, done.stdout, done.stderr) == (0, "9 <mujoco\n", "")


OPENGL_ADVICE = (
    "set MUJOCO_GL=egl (GPU or Mesa EGL) or MUJOCO_GL=osmesa (software rendering), install the library it "
    "needs, or unset it"
)


@pytest.mark.parametrize(
    ("backend", "words", "reason"),
    [
        (
            "bogus",
            ["render", "Sparrow7", "-o", "x.png"],
            "invalid value for environment variable MUJOCO_GL: bogus",
        ),
        (
            "bogus",
            ["build", "Sparrow7", "-o", "x.xml"],
            "invalid value for environment variable MUJOCO_GL: bogus",
        ),
        ("osmesa", ["render", "Sparrow7", "-o", "x.png"], "its OpenGL library cannot be loaded ("),
        ("osmesa", ["list", "bases"], "its OpenGL library cannot be loaded ("),
    ],
)
def test_a_mujoco_gl_that_mujoco_cannot_start_is_one_line(
    backend: str, words: list[str], reason: str, tmp_path: Path
) -> None:
    """Found by the hostile-input battery: MuJoCo starts its OpenGL backend when it is imported, so a
    MUJOCO_GL it does not know, or osmesa without the OSMesa library, was a traceback in any command."""
    if backend == "osmesa" and ctypes.util.find_library("OSMesa"):
        pytest.skip("OSMesa is installed here")
    # As a user's shell has it: not the PyOpenGL platform an earlier render in this process chose.
    clean = {name: value for name, value in os.environ.items() if name != "PYOPENGL_PLATFORM"}
    done = subprocess.run(
        [sys.executable, "-c", CLI, *words],
        cwd=tmp_path,
        capture_output=True,
        text=True,
        env={**clean, "MUJOCO_GL": backend},
        timeout=300,
    )
    (line,) = done.stderr.splitlines()
    assert done.returncode == 1
    assert line.startswith(f"MuJoCo cannot start with MUJOCO_GL={backend}: {reason}")
    assert line.endswith(f"; {OPENGL_ADVICE}")
    assert os.listdir(tmp_path) == []
