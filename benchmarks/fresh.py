"""Target 6's scale test, in fresh processes: scenes of N robots, per-robot assembly and compile
time and each process's peak memory."""

from __future__ import annotations

from benchmarks.figures import Figure, ratio_figure
from benchmarks.timing import fresh_medians, in_fresh_process

SCALE_TARGET = 1.2


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
        "6 scale",
        f"N={last['robots']} vs N={first['robots']}",
        last["total_per_robot"],
        f"N={first['robots']}",
        first["total_per_robot"],
        SCALE_TARGET,
        "time per robot (assemble + compile)",
    )
    return rows, figure
