"""Instructions executed by whole processes, counted by valgrind's callgrind: the warm figures (target 2)
checked by a count the machine's load does not change. Wall times on a shared machine move with
other work by 20% and more between runs; the number of instructions a process runs does not.

The same snippets as :func:`benchmarks.whole.warm` (the floor: ``import mujoco`` and loading the
cached ``.mjb``; ours: ``import assembler`` and ``assemble(name).get_model()``, ``get_xml()``,
``load_model(name)``), each run once under callgrind (about fifty times slower than without), in
the cache :func:`~benchmarks.whole.warm` filled. Skipped when valgrind is not installed.
"""

from __future__ import annotations

import re
import shutil
import subprocess
import sys

from benchmarks.figures import Figure, ratio_figure
from benchmarks.processes import environment
from benchmarks.timing import REPOSITORY
from benchmarks.whole import entry_path

_COLLECTED = re.compile(r"Collected : (\d+)")


def available() -> bool:
    """Whether valgrind is on the path."""
    return shutil.which("valgrind") is not None


def count(code: str, env: dict[str, str]) -> int:
    """Instructions a new ``python -c code`` process executes, start-up and exit included."""
    done = subprocess.run(
        ["valgrind", "--tool=callgrind", "--callgrind-out-file=/dev/null", sys.executable, "-c", code],
        capture_output=True,
        text=True,
        cwd=REPOSITORY,
        env=environment(env),
        timeout=1800,
    )
    found = _COLLECTED.search(done.stderr)
    if done.returncode != 0 or found is None:
        last = (done.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"callgrind of {code[:80]!r}: exit {done.returncode}: {last}")
    return int(found.group(1))


def warm(name: str, env: dict[str, str]) -> list[Figure]:
    """Ours against the floor in instructions, for a robot the cache ``env`` names holds."""
    floor = count(f"import mujoco; mujoco.MjModel.from_binary_path({entry_path(name, env)!r})", env)
    cases = {
        "assemble().get_model()": f"import assembler; assembler.assemble({name!r}).get_model()",
        "assemble().get_xml()": f"import assembler; assembler.assemble({name!r}).get_xml()",
        "load_model": f"import assembler; assembler.load_model({name!r})",
    }
    return [
        ratio_figure(
            "2 warm",
            f"{name} {subject}, instructions",
            count(code, env),
            "MuJoCo .mjb load, whole process",
            floor,
            None,
            "callgrind, whole process; no target: instructions are not time (memory-bound work counts "
            "few of them), a load-independent figure to compare between runs and commits",
            unit="instructions",
        )
        for subject, code in cases.items()
    ]
