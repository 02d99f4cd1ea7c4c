"""robosuite environments with robots built from specs, against the same environments with
robosuite's own robot classes: ``robosuite.make`` and ``env.reset()`` (a hard reset rebuilds every
model, so a training loop pays it at every episode).

Each side runs in its own new process (robosuite's registries are process-wide): the stock side
imports robosuite alone; ours imports ``assembler.robosuite`` and replaces the robot, its gripper
and base by our specs of the same names (``replace_robosuite``), as robosuite's test plugin does.
The whole-process figure is the wall time of a script that makes the environment and resets it
``RESETS`` times; the in-process figures are ``make`` and the median reset, timed inside. Each note
gives the same ratio in CPU time (the process's, or ``time.process_time`` inside it), steadier than
wall time on a shared machine. Issue 27's target: ours at or below robosuite's own (<= 1x), whole
process and in-process, with the part files already kept in the cache (a warm make; every process
after the first for a robot).

On a MuJoCo robosuite cannot step on unpatched (4.0), the stock side gets the bridge's patches too
(:mod:`assembler.robosuite.compat`, imported alone): robosuite's own classes fail there otherwise.
"""

from __future__ import annotations

from benchmarks.figures import Figure, ratio_figure
from benchmarks.processes import Run, medians, run_python

RESETS = 5
"""Hard resets per process (the first reset after make rebuilds the model like every later one)."""

CASES: tuple[tuple[str, str], ...] = (("Lift", "Panda"), ("Lift", "Sawyer"), ("TwoArmLift", "Baxter"))
"""Environment and robot of each measure (a single arm, another arm, a bimanual robot)."""

_WORK = """\
import time, statistics
kwargs = dict(has_renderer=False, has_offscreen_renderer=False, use_camera_obs=False)
_made, _made_cpu = time.perf_counter(), time.process_time()
env = robosuite.make({env!r}, robots={robot!r}, **kwargs)
out["make"], out["make_cpu"] = time.perf_counter() - _made, time.process_time() - _made_cpu
resets, cpus = [], []
for _ in range({resets}):
    _reset, _reset_cpu = time.perf_counter(), time.process_time()
    env.reset()
    resets.append(time.perf_counter() - _reset)
    cpus.append(time.process_time() - _reset_cpu)
out["reset"], out["reset_cpu"] = statistics.median(resets), statistics.median(cpus)
"""

_OURS = "import assembler.robosuite, robosuite\nassembler.robosuite.replace_robosuite()"
_STOCK = "import robosuite"
_STOCK_PATCHED = "import robosuite, assembler.robosuite.compat as _c\n_c.apply_all()"


def _stock_imports() -> str:
    """robosuite alone, or with the bridge's MuJoCo patches where this MuJoCo needs them."""
    needed = run_python("import assembler.robosuite.compat as c", "out['n'] = c.apply_all()")
    return _STOCK_PATCHED if "applied" in needed.inner["n"].values() else _STOCK


def _run(imports: str, env: str, robot: str) -> Run:
    return run_python(imports, _WORK.format(env=env, robot=robot, resets=RESETS))


def _cpu(mine: Run, theirs: Run, key: str | None = None) -> str:
    """The CPU-time ratio, ours / robosuite's, of the whole processes or of the inner figure ``key``."""
    ours_cpu = mine.cpu if key is None else mine.inner[key]
    return f"CPU {ours_cpu / (theirs.cpu if key is None else theirs.inner[key]):.2f}x"


def environment_figures(repeats: int) -> list[Figure]:
    """Make and reset, ours against stock, per case: whole process and in-process, the part files
    kept (one unmeasured make of ours first)."""
    figures = []
    stock_imports = _stock_imports()
    for env, robot in CASES:
        _run(_OURS, env, robot)  # the part files of this robot kept: what every later process finds
        ours: list[Run] = []
        stock: list[Run] = []
        for index in range(repeats):  # interleaved, the order alternating
            for side in ("ours", "stock") if index % 2 == 0 else ("stock", "ours"):
                runs, imports = (ours, _OURS) if side == "ours" else (stock, stock_imports)
                runs.append(_run(imports, env, robot))
        mine, theirs = medians(ours), medians(stock)
        subject = f"{env} {robot}"
        whole = f"make + {RESETS} resets, whole process; {_cpu(mine, theirs)}"
        figures += [
            ratio_figure("environment", subject, mine.wall, "robosuite's classes", theirs.wall, 1.0, whole),
            ratio_figure(
                "environment",
                f"{subject} make",
                mine.inner["make"],
                "robosuite's classes",
                theirs.inner["make"],
                1.0,
                f"robosuite.make, in-process; {_cpu(mine, theirs, 'make_cpu')}",
            ),
            ratio_figure(
                "environment",
                f"{subject} reset",
                mine.inner["reset"],
                "robosuite's classes",
                theirs.inner["reset"],
                1.0,
                f"one hard reset (median), in-process; {_cpu(mine, theirs, 'reset_cpu')}",
            ),
        ]
    return figures
