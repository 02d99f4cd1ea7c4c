"""MuJoCo Warp batches: how long N randomized worlds of a robot take to prepare, against one compile.

``python -m benchmarks.warp_batch [--worlds 4096] [--robots Sparrow7 Panda]`` (needs the ``warp``
extra; the Panda needs robosuite's model files). Per robot: one compile of the robot from scratch
(cache off, median of three), then ``put_variants`` of a plan with N worlds (a damping grid of four
values times N/4 seeded draws of a link's mass factor and a joint's armature) and its ratio to the
compile against the target (20 compiles' time); the CPU part of it (the plan validated and probed
once, every world's values in arrays: ``laws`` yes, or each world patched: no) and the rest
(``put_model``, ``make_data``, ``set_const``, ``forward`` on the device). Peak memory: what Python
and numpy allocate during ``put_variants`` (tracemalloc, a run of its own) and the process's peak
resident size. Warp's kernels are compiled by a small batch first, so the figures are warm.
"""

from __future__ import annotations

import argparse
import resource
import statistics
import time
import tracemalloc

import numpy as np

import assembler
from assembler.warp import batch as batch_module
from assembler.warp import put_variants
from assembler.warp.seeded_draws import plan_columns
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan

TARGET = 20.0
"""Issue 36's target: N worlds prepared in at most this many compiles' time (measured in the same run)."""

LINKS = {"Sparrow7": ("link3", "joint2"), "Panda": ("link3", "joint2")}


def plan_of(robot: str, worlds: int) -> VariantPlan:
    """Four damping values times ``worlds / 4`` draws of a link's mass factor and a joint's armature."""
    link, joint = LINKS[robot]
    return VariantPlan(
        robot,
        fixed=(f"bodies=[{{match: {link}, mass_scale: 1}}]", f"joints=[{{match: {joint}, armature: 0.1}}]"),
        grids=(Grid.parse("joint_defaults.damping=0.05,0.1,0.2,0.4"),),
        draws=(
            Draw.parse("bodies[0].mass_scale=0.8:1.2", "uniform"),
            Draw.parse("joints[0].armature=0.05:0.5", "uniform"),
        ),
        random=max(1, worlds // 4),
        seed=1,
    )


def compile_seconds(robot: str) -> float:
    """Median of three compiles of the robot from scratch (no cache)."""
    times = []
    for _ in range(3):
        start = time.perf_counter()
        assembler.assemble(robot).get_model(cache=False, store=False)
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def cpu_seconds(plan: VariantPlan) -> float:
    """Seconds of the CPU part of ``put_variants`` (the robot's compile excluded): the plan validated
    and probed once, every world's values computed in arrays, two worlds checked against the CPU patch."""
    robot = assembler.assemble(plan.robot, overrides=list(plan.fixed))
    model = robot.get_model()
    start = time.perf_counter()
    plan.check()
    indices = np.arange(plan.size)
    columns = plan_columns(plan, range(plan.size))
    effects = batch_module.laws_of(plan, robot, model, columns)
    rows = batch_module.world_rows(plan, robot, model, effects, indices, columns)
    fields = batch_module.model_fields()
    batch_module.checked_worlds(plan, robot, model, rows, fields, batch_module.batchable_fields())
    return time.perf_counter() - start


def peak_megabytes(plan: VariantPlan) -> float:
    """Peak of the memory Python and numpy allocate during ``put_variants`` (tracemalloc; a run of its own,
    since tracing slows it; Warp's arrays are counted by the process's peak resident size)."""
    tracemalloc.start()
    put_variants(plan)
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak / 2**20


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--worlds", type=int, default=4096)
    parser.add_argument("--robots", nargs="+", default=["Sparrow7", "Panda"])
    args = parser.parse_args(argv)
    columns = (
        "robot",
        "worlds",
        "compile s",
        "prepare s",
        "cpu part s",
        "ratio",
        "target",
        "laws",
        "peak MB",
        "rss MB",
    )
    print("  ".join(f"{c:>10}" for c in columns), flush=True)
    for robot in args.robots:
        put_variants(plan_of(robot, 4))  # Warp loads (or compiles) this robot's kernels: not timed
        one = compile_seconds(robot)
        plan = plan_of(robot, args.worlds)
        start = time.perf_counter()
        batch = put_variants(plan)
        prepare = time.perf_counter() - start
        cpu = cpu_seconds(plan)
        peak = peak_megabytes(plan)
        rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
        ratio = prepare / one
        target = f"{'met' if ratio <= TARGET else 'missed'} {TARGET:g}x"
        laws = "yes" if batch.effects is not None else "no"
        cells = (
            robot,
            batch.nworld,
            f"{one:.3f}",
            f"{prepare:.2f}",
            f"{cpu:.2f}",
            f"{ratio:.1f}x",
            target,
            laws,
        )
        cells += (f"{peak:.0f}", f"{rss:.0f}")
        print("  ".join(f"{c:>10}" for c in cells), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
