"""MuJoCo Warp batches: how long N randomized worlds of a robot take to prepare, against one compile.

``python -m benchmarks.warp_batch [--worlds 4096] [--robots Sparrow7 Panda]`` (needs the ``warp``
extra; the Panda needs robosuite's model files). Per robot: one compile of the robot from scratch
(cache off, median of three), then ``put_variants`` of a plan with N worlds (a damping grid of four
values times N/4 seeded draws of a link's mass factor and a joint's armature), split into the CPU
part (each world's spec resolved and patched onto the one compiled model, derived constants
recomputed) and the rest (``put_model``, ``put_data``, ``set_const``, ``forward`` on the device).
Warp's kernels are compiled by a small batch first, so the figures are warm.
"""

from __future__ import annotations

import argparse
import statistics
import time

import assembler
from assembler.warp import put_variants
from assembler.warp.batch import variant_items
from assembler.warp.world_values import world_patches, world_values
from assembler.worlds.variants.plan import Draw, Grid, VariantPlan

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
    """Seconds of the CPU part of ``put_variants``: resolve and patch every world (one compile excluded)."""
    robot = assembler.assemble(plan.robot, overrides=list(plan.fixed))
    model = robot.get_model()
    start = time.perf_counter()
    items = variant_items(plan, plan.variant_overrides())
    patches = world_patches(robot, model, items, [str(i) for i in range(len(items))])
    world_values(model, patches, sorted({f for p in patches for f in p.fields}))
    return time.perf_counter() - start


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--worlds", type=int, default=4096)
    parser.add_argument("--robots", nargs="+", default=["Sparrow7", "Panda"])
    args = parser.parse_args(argv)
    columns = ("robot", "worlds", "compile s", "prepare s", "cpu part s", "ratio", "per world ms")
    print("  ".join(f"{c:>12}" for c in columns), flush=True)
    for robot in args.robots:
        put_variants(plan_of(robot, 4))  # Warp loads (or compiles) this robot's kernels: not timed
        one = compile_seconds(robot)
        plan = plan_of(robot, args.worlds)
        start = time.perf_counter()
        batch = put_variants(plan)
        prepare = time.perf_counter() - start
        cpu = cpu_seconds(plan)
        ratio, per_world = f"{prepare / one:.1f}x", f"{prepare / batch.nworld * 1e3:.3f}"
        cells = (robot, batch.nworld, f"{one:.3f}", f"{prepare:.2f}", f"{cpu:.2f}", ratio, per_world)
        print("  ".join(f"{c:>12}" for c in cells), flush=True)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
