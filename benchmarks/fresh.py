"""Measurements made in fresh processes: the first load of a robot (cold, with an empty cache),
the first load in a new process once the cache holds it (warm), the scale test's scenes (with
each process's peak memory), and start-up."""

from __future__ import annotations

from pathlib import Path
from typing import Any

import assembler
from benchmarks.figures import Figure, ratio_figure, seconds_text, speedup_figure
from benchmarks.timing import fresh_medians, in_fresh_process

COLD_TARGET = 1.05
WARM_SPEEDUP_TARGET = 10.0
WARM_FLOOR_TARGET = 1.2
SCALE_TARGET = 1.2
STARTUP_TARGET = 0.3


def _ours(name: str, cache_root: Path, index: int) -> dict[str, Any]:
    """Cold then warm, in two new processes sharing a cache folder that starts empty."""
    for attempt in range(2):  # a concurrent edit of the assembler's code changes every key: redo once
        env = {"ASSEMBLER_CACHE_DIR": str(cache_root / f"{name}-{index}-{attempt}")}
        cold = in_fresh_process("ours-cold", name, env=env)
        warm = in_fresh_process("ours-warm", name, str(index % 2), env=env)
        if warm["hits"] == 1:
            break
    return {
        "cold": cold["total"],
        "cold_create": cold["create"],
        "write": cold["write"],
        "warm": warm["total"],
        "floor": warm["floor"],
        "warm_hit": warm["hits"],
    }


def cold_and_warm(name: str, robosuite: bool, cache_root: Path, xml_file: Path, repeats: int) -> list[Figure]:
    """Cold load against MuJoCo's compile of the same robot's XML (robosuite's for its robots),
    warm load against robosuite's cold load and against MuJoCo loading the cached model."""
    if robosuite:
        reference = lambda index: in_fresh_process("robosuite-cold", name)  # noqa: E731
    else:
        xml_file.write_text(assembler.assemble(name).get_xml())
        reference = lambda index: in_fresh_process("xml-compile", str(xml_file))  # noqa: E731
    results = fresh_medians({"reference": reference, "ours": lambda i: _ours(name, cache_root, i)}, repeats)
    ours, ref = results["ours"], results["reference"]
    compile_name = "MuJoCo compile (robosuite XML)" if robosuite else "MuJoCo compile (our XML)"
    note = (
        f"assemble {seconds_text(ours['cold_create'])}; entry written after, in {seconds_text(ours['write'])}"
    )
    warm_note = "" if ours["warm_hit"] >= 1 else "NOT a cache hit"
    figures = [ratio_figure("cold load", name, ours["cold"], compile_name, ref["compile"], COLD_TARGET, note)]
    if robosuite:
        figures.append(
            speedup_figure(
                "warm load", name, ours["warm"], "robosuite cold", ref["total"], WARM_SPEEDUP_TARGET
            )
        )
    figures.append(
        ratio_figure(
            "warm load", name, ours["warm"], "MuJoCo .mjb load", ours["floor"], WARM_FLOOR_TARGET, warm_note
        )
    )
    return figures


def scale(counts: list[int], repeats: int) -> tuple[list[dict[str, float]], Figure]:
    """Scenes of N robots: per-robot assembly and compile time, and peak memory, per N; the
    figure compares the per-robot time at the largest N with N = 1."""
    cases = {str(n): (lambda index, n=n: in_fresh_process("scene", str(n))) for n in counts}
    results = fresh_medians(cases, repeats)
    rows = []
    for n in counts:
        r = results[str(n)]
        rows.append(
            {
                "robots": n,
                "assemble_per_robot": r["assemble"] / n,
                "compile_per_robot": r["compile"] / n,
                "total_per_robot": (r["assemble"] + r["compile"]) / n,
                "peak_bytes": r["peak_bytes"],
                "added_bytes_per_robot": r["added_bytes"] / n,
            }
        )
    first, last = rows[0], rows[-1]
    figure = ratio_figure(
        "scale",
        f"N={last['robots']} vs N={first['robots']}",
        last["total_per_robot"],
        f"N={first['robots']}",
        first["total_per_robot"],
        SCALE_TARGET,
        "time per robot (assemble + compile)",
    )
    return rows, figure


def startup(repeats: int) -> list[Figure]:
    """``import assembler`` (registering every shipped spec) against ``import mujoco`` alone."""
    results = fresh_medians(
        {
            "mujoco": lambda index: in_fresh_process("startup-mujoco"),
            "assembler": lambda index: in_fresh_process("startup-assembler"),
        },
        repeats,
    )
    ours, reference = results["assembler"]["import"], results["mujoco"]["import"]
    above = ours - reference
    robots = int(results["assembler"]["robots"])
    return [
        ratio_figure(
            "start-up", "import", ours, "import mujoco", reference, None, f"{robots} robots registered"
        ),
        ratio_figure(
            "start-up",
            "above mujoco",
            above,
            "target",
            STARTUP_TARGET,
            1.0,
            f"{seconds_text(above)} above import mujoco",
        ),
    ]
