"""Whole processes, timed from outside: a new ``python -c`` (or a command) per run, its wall time
from spawn to exit (start-up, imports, the work, and the exit, which waits for the cache entry's
writer) and its CPU time, plus what it measured inside itself (the in-process part).

A snippet is given as its imports and its work; the child times the work alone and prints it as
one JSON line with anything the work put in ``out``. Nothing else runs in the child, so the
whole-process figure is what a user's script costs.
"""

from __future__ import annotations

import compileall
import json
import os
import resource
import subprocess
import sys
import time
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

from benchmarks.timing import REPOSITORY, median

_WRAPPER = """\
import time as _t, sys as _s, json as _j
out = {{}}
{imports}
_start = _t.perf_counter()
{work}
out["inside"] = _t.perf_counter() - _start
_s.stdout.write("\\nBENCH " + _j.dumps(out) + "\\n")
"""


@dataclass(frozen=True)
class Run:
    """One process: wall and CPU seconds of the whole of it, and what it measured inside."""

    wall: float
    cpu: float
    inner: dict[str, Any] = field(default_factory=dict)


def environment(extra: Mapping[str, str] | None = None) -> dict[str, str]:
    """The children's environment: this one, the repository importable, plus ``extra``."""
    env = {**os.environ, **(extra or {})}
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(REPOSITORY), env.get("PYTHONPATH")]))
    return env


def compile_bytecode() -> None:
    """Compile the repository's Python files to bytecode before any process is timed, as ``pip
    install`` does for an installed package. With ``PYTHONDONTWRITEBYTECODE`` set (as on some
    shared machines) no bytecode is ever written, so every new process would compile each of our
    modules from source (0.3-0.5 s for the spec layer) while mujoco's and robosuite's, installed
    with their bytecode, load it: a cost no installed copy of the assembler pays."""
    for folder in ("assembler", "benchmarks", "tests"):
        compileall.compile_dir(REPOSITORY / folder, quiet=1)


def run_command(command: Sequence[str], env: Mapping[str, str] | None = None) -> Run:
    """Run ``command`` to its end; its wall and CPU time and the JSON it printed after ``BENCH``."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    done = subprocess.run(
        list(command), capture_output=True, text=True, cwd=REPOSITORY, env=environment(env), timeout=900
    )
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if done.returncode != 0:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"{' '.join(command)[:160]}: exit {done.returncode}: {last}")
    inner: dict[str, Any] = {}
    for line in done.stdout.splitlines():
        if line.startswith("BENCH "):
            inner = json.loads(line.removeprefix("BENCH "))
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return Run(wall, cpu, inner)


def run_python(imports: str, work: str, env: Mapping[str, str] | None = None) -> Run:
    """A new interpreter running ``imports`` then ``work`` (timed inside as ``inside``)."""
    code = _WRAPPER.format(imports=imports, work=work)
    return run_command([sys.executable, "-c", code], env)


def medians(runs: Sequence[Run]) -> Run:
    """Medians of wall, CPU and every inner figure over ``runs``."""
    keys = {key for run in runs for key, value in run.inner.items() if isinstance(value, (int, float))}
    inner = {key: median([float(run.inner[key]) for run in runs if key in run.inner]) for key in keys}
    return Run(median([run.wall for run in runs]), median([run.cpu for run in runs]), inner)


def wait_for_process(pid: int, limit: float = 300.0) -> None:
    """Wait until process ``pid`` (not our child: a mesh filler in its own session) has ended."""
    deadline = time.monotonic() + limit
    while time.monotonic() < deadline:
        try:
            with open(f"/proc/{pid}/stat") as stat:
                if stat.read().split(")")[-1].split()[0] == "Z":
                    return
        except OSError:
            return
        time.sleep(0.02)
