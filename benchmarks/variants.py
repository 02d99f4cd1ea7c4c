"""Target 5: variants. Per variant, ours (``write_variants`` with one job: assemble, build, compile
with stored meshes, emit, write) against robosuite doing the same variants in one process (create
the robot, set the varied joint damping, ``get_xml``), each in a new process timed inside; and
robosuite with MuJoCo compiling each XML too, since every one of our variant files is compiled
before it is written. Then ``assembler variants --jobs 1`` against ``--jobs 2``, whole processes.
"""

from __future__ import annotations

from pathlib import Path

from benchmarks.figures import Figure, ratio_figure, seconds_text
from benchmarks.processes import Run, medians, run_command, run_python
from benchmarks.whole import ASSEMBLER, _cache

VARIANT_TARGET = 1.0
JOBS_TARGET = 1.6
"""Two jobs on two cores: close to twice as fast (the issue's "close to 2x")."""


def _values(count: int) -> list[float]:
    return [round(0.05 + 0.01 * index, 4) for index in range(count)]


def _ours(name: str, count: int, folder: Path, env: dict[str, str]) -> Run:
    grid = "joint_defaults.damping=" + ",".join(str(v) for v in _values(count))
    imports = "from assembler.worlds.variants import Grid, VariantPlan, write_variants"
    work = (
        f"write_variants(VariantPlan(robot={name!r}, grids=(Grid.parse({grid!r}),), jobs=1), {str(folder)!r})"
    )
    return run_python(imports, work, env)


def _robosuite(name: str, count: int, compile_too: bool) -> Run:
    imports = "import numpy as np, mujoco\nfrom tests.parity.robosuite_side import robosuite_robot_model"
    work = (
        f"for value in {_values(count)!r}:\n"
        f"    robot = robosuite_robot_model({name!r})\n"
        "    robot.set_joint_attribute('damping', np.full(robot.dof, value))\n"
        "    xml = robot.get_xml()\n" + ("    mujoco.MjModel.from_xml_string(xml)\n" if compile_too else "")
    )
    return run_python(imports, work)


def per_variant(name: str, count: int, scratch: Path, repeats: int) -> list[Figure]:
    """Per-variant seconds (whole sweep timed inside a new process, divided by ``count``)."""
    filled = scratch / f"meshes-{name}"
    runs: dict[str, list[Run]] = {"ours": [], "robosuite": [], "robosuite+compile": []}
    for index in range(repeats):
        env = _cache(scratch / f"v-{name}-{index}", filled)
        order = list(runs) if index % 2 == 0 else list(runs)[::-1]
        for case in order:
            if case == "ours":
                runs[case].append(_ours(name, count, scratch / f"variants-{name}-{index}", env))
            else:
                runs[case].append(_robosuite(name, count, compile_too=case.endswith("compile")))
    each = {case: medians(results).inner["inside"] / count for case, results in runs.items()}
    note = f"{count} variants of joint_defaults.damping, one process each side, meshes stored"
    return [
        ratio_figure(
            "5 variants",
            f"{name} per variant",
            each["ours"],
            "robosuite get_xml per variant",
            each["robosuite"],
            VARIANT_TARGET,
            note,
        ),
        ratio_figure(
            "5 variants",
            f"{name} per variant",
            each["ours"],
            "robosuite get_xml + MuJoCo compile",
            each["robosuite+compile"],
            None,
            "ours compiles every variant before writing it",
        ),
    ]


def jobs(name: str, count: int, scratch: Path, repeats: int) -> list[Figure]:
    """``assembler variants`` with ``--jobs 1`` against ``--jobs 2`` (whole processes)."""
    grid = "joint_defaults.damping=" + ",".join(str(v) for v in _values(count))
    filled = scratch / f"meshes-{name}"
    walls: dict[int, list[float]] = {1: [], 2: []}
    for index in range(repeats):
        for workers in (1, 2) if index % 2 == 0 else (2, 1):
            env = _cache(scratch / f"j-{name}-{workers}-{index}", filled)
            folder = scratch / f"jobs-{name}-{workers}-{index}"
            command = [ASSEMBLER, "variants", name, "--grid", grid, "--jobs", str(workers), "-o", str(folder)]
            walls[workers].append(run_command(command, env).wall)
    one, two = (medians([Run(w, 0.0) for w in walls[n]]).wall for n in (1, 2))
    speedup = one / two
    return [
        ratio_figure(
            "5 variants",
            f"{name} --jobs 2 vs --jobs 1",
            two,
            "--jobs 1",
            one,
            1 / JOBS_TARGET,
            f"{count} variants; --jobs 2 is {speedup:.2f}x faster "
            f"({seconds_text(two)} vs {seconds_text(one)})",
        )
    ]
