"""Command-line cases of the held-out battery: a closed standard output, Ctrl-C with worker processes,
``--set`` given many times, ``--specs`` repeated. Each ends with at most one line per problem and the
right exit code, in a new process as a user runs it."""

from __future__ import annotations

import contextlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from assembler.cli import main
from assembler.cli.arguments import parse
from assembler.spec.documents import parse_overrides
from assembler.worlds.variants.effects import superseded

CLI = "import sys; from assembler.cli import run; sys.exit(run())"

# fmt: off
CLOSED_STDOUT = [
    pytest.param(["list", "robots"], 1, "cannot write to standard output: it was closed (>&-)\n", id="list"),
    pytest.param(["build", "Sparrow7", "-o", "out.xml"], 0, "wrote out.xml\n", id="build-to-a-file-needs-no-stdout"),
]
# fmt: on


@pytest.mark.parametrize(("argv", "code", "err"), CLOSED_STDOUT)
def test_a_closed_standard_output_is_at_most_one_line(
    argv: list[str], code: int, err: str, tmp_path: Path
) -> None:
    # `assembler list >&-`: the shell starts the command with descriptor 1 closed.
    done = subprocess.run(
        ["sh", "-c", 'exec "$0" "$@" >&-', sys.executable, "-c", CLI, *argv],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        text=True,
        check=False,
    )
    assert (done.returncode, done.stderr) == (code, err)


def _children(pid: int) -> list[int]:
    try:
        return [int(n) for n in Path(f"/proc/{pid}/task/{pid}/children").read_text().split()]
    except OSError:
        return []


@pytest.mark.skipif(not Path("/proc/self/task").exists(), reason="needs /proc to see the worker processes")
def test_ctrl_c_during_variants_with_workers_prints_one_line(tmp_path: Path) -> None:
    # A description per variant: not a patchable field, so every variant is compiled (milliseconds
    # each); 5,000 of them are still building when the first files are written and Ctrl-C comes.
    values = ",".join(f"run{index}" for index in range(5000))
    command = subprocess.Popen(
        [sys.executable, "-c", CLI, "variants", "Biped", "--grid", f"description={values}"]
        + ["--no-cache", "--jobs", "2", "-o", "out"],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,  # its own process group: Ctrl-C at a terminal reaches the whole group
    )
    deadline = time.monotonic() + 120
    written = tmp_path / "out"
    while time.monotonic() < deadline and not (
        len(_children(command.pid)) >= 2 and written.is_dir() and any(written.glob("Biped_*.xml"))
    ):
        time.sleep(0.05)
    os.killpg(command.pid, signal.SIGINT)
    _, err = command.communicate(timeout=120)
    assert (command.returncode, err) == (130, "interrupted\n")
    assert not [path for path in (tmp_path / "out").glob("*") if path.name.endswith(".tmp")]


@pytest.mark.parametrize("delay", [0.0, 0.05, 0.2])
def test_ctrl_c_as_a_run_with_workers_ends_is_never_a_death_by_sigint(delay: float, tmp_path: Path) -> None:
    # Ctrl-C just after the last line: the command has ended (0) or is still ending (130), never -2
    # (the interpreter, exiting and joining the worker pool, restores the default handler).
    with subprocess.Popen(
        [sys.executable, "-c", CLI, "variants", "Biped", "--grid", "description=a,b,c,d"]
        + ["--no-cache", "--jobs", "2", "-o", "out"],
        cwd=tmp_path,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    ) as command:
        assert command.stderr is not None
        said = command.stderr.readline()
        time.sleep(delay)
        with contextlib.suppress(ProcessLookupError):
            os.killpg(command.pid, signal.SIGINT)
        rest = command.stderr.read()
    assert said.startswith("wrote 4 of 4 variants of Biped to out")
    assert (command.wait(timeout=120), rest.endswith("interrupted\n")) in ((0, False), (130, True))


def test_an_override_a_later_one_replaces_is_found_without_building() -> None:
    flags = [f"joint_defaults.damping={0.1 + i / 10000}" for i in range(1280)]
    flags += ["init_qpos[1]=0.2", "joint_defaults.armature=0.1", "joint_defaults={damping: 0.4}"]
    found = superseded(parse_overrides(flags, label="--set "))
    assert found == [True] * 1280 + [False, True, False]


def test_set_given_1280_times_builds_once_and_says_so(
    tmp_path: Path, capsys: pytest.CaptureFixture[str]
) -> None:
    flags = [f"--set=joint_defaults.damping={0.1 + i / 10000}" for i in range(1280)]
    assert main(["build", "Sparrow7", "--no-cache", "-o", str(tmp_path / "out.xml"), *flags]) == 0
    assert capsys.readouterr().err.splitlines() == [
        f"wrote {tmp_path}/out.xml",
        "warning: --set joint_defaults.damping is given 1280 times; only the last counts",
    ]


def test_a_bad_set_among_many_writes_nothing(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    (tmp_path / "out.xml").write_text("earlier output\n")
    flags = [f"--set=joint_defaults.damping={0.1 + i / 10000}" for i in range(1280)]
    argv = [
        "build",
        "Sparrow7",
        "--no-cache",
        "-o",
        str(tmp_path / "out.xml"),
        *flags,
        "--set=joint_defaults.damping=-1",
    ]
    assert main(argv) == 1
    assert capsys.readouterr().err.startswith("--set joint_defaults.damping: ")
    assert (tmp_path / "out.xml").read_text() == "earlier output\n"


def test_a_repeated_specs_folder_is_read_once(tmp_path: Path) -> None:
    (tmp_path / "specs").mkdir()
    args = parse(
        [
            "--specs",
            str(tmp_path / "specs"),
            "list",
            "--specs",
            f"{tmp_path}/specs/",
            "--specs",
            str(tmp_path / "specs" / "."),
        ]
    )
    assert args.specs == [str(tmp_path / "specs")]
