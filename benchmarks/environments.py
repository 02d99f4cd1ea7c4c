"""robosuite environments with robots built from specs, against the same environments with
robosuite's own robot classes: ``robosuite.make`` and ``env.reset()`` (a hard reset rebuilds every
model, so a training loop pays it at every episode).

Each side runs in its own new process (robosuite's registries are process-wide): the stock side
imports robosuite alone; ours imports ``assembler.robosuite`` and replaces the robot, its gripper
and base by our specs of the same names (``replace_robosuite``), as robosuite's test plugin does.
The whole-process figure is the wall time of a script that makes the environment and resets it
``RESETS`` times; the in-process figures are ``make`` and the median reset, timed inside. No
target is set by the issue: the figure says what a user pays for the exactness of the bridge.
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
_made = time.perf_counter()
env = robosuite.make({env!r}, robots={robot!r}, **kwargs)
out["make"] = time.perf_counter() - _made
resets = []
for _ in range({resets}):
    _reset = time.perf_counter()
    env.reset()
    resets.append(time.perf_counter() - _reset)
out["reset"] = statistics.median(resets)
"""

_OURS = "import assembler.robosuite, robosuite\nassembler.robosuite.replace_robosuite()"
_STOCK = "import robosuite"


def _run(imports: str, env: str, robot: str) -> Run:
    return run_python(imports, _WORK.format(env=env, robot=robot, resets=RESETS))


def environment_figures(repeats: int) -> list[Figure]:
    """Make and reset, ours against stock, per case: whole process and in-process."""
    figures = []
    for env, robot in CASES:
        ours: list[Run] = []
        stock: list[Run] = []
        for index in range(repeats):  # interleaved, the order alternating
            for side in ("ours", "stock") if index % 2 == 0 else ("stock", "ours"):
                runs, imports = (ours, _OURS) if side == "ours" else (stock, _STOCK)
                runs.append(_run(imports, env, robot))
        mine, theirs = medians(ours), medians(stock)
        subject = f"{env} {robot}"
        whole = f"make + {RESETS} resets, whole process"
        figures += [
            ratio_figure("environment", subject, mine.wall, "robosuite's classes", theirs.wall, note=whole),
            ratio_figure(
                "environment",
                f"{subject} make",
                mine.inner["make"],
                "robosuite's classes",
                theirs.inner["make"],
                note="robosuite.make, in-process",
            ),
            ratio_figure(
                "environment",
                f"{subject} reset",
                mine.inner["reset"],
                "robosuite's classes",
                theirs.inner["reset"],
                note="one hard reset (median), in-process",
            ),
        ]
    return figures
