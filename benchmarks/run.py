"""The benchmark harness: ``python -m benchmarks [--quick] [--output DIR] [--robots A,B]``.

It measures, and prints as ratios against their references, the issue's five figures: assemble,
cold load, warm load (and repeated load in one process), scale, and start-up. Every robot of
``specs/robosuite/robots`` is compared with robosuite itself (robots that fail to build on either
side are reported and skipped); our own robots are compared with MuJoCo on our emitted XML. The
model cache used is a temporary folder, never the user's. A full run writes
``benchmarks/results.json`` and ``benchmarks/results.md``; ``--quick`` (a smoke run on Sparrow7,
and Panda when robosuite is installed) writes only where ``--output`` says.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
import traceback
from pathlib import Path
from typing import Any

from benchmarks.figures import Figure
from benchmarks.report import machine, markdown, write_json

HERE = Path(__file__).resolve().parent


def _arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="smoke run: few robots, one repetition")
    parser.add_argument("--output", type=Path, help="folder for results.json and results.md")
    parser.add_argument("--robots", help="comma-separated robot names instead of all")
    parser.add_argument("--repeats", type=int, help="fresh-process repetitions (default 3; quick: 1)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = _arguments(argv)
    with tempfile.TemporaryDirectory(prefix="assembler-bench-") as scratch:
        os.environ["ASSEMBLER_CACHE_DIR"] = str(Path(scratch) / "cache")  # never the user's cache
        os.environ.pop("ASSEMBLER_NO_CACHE", None)
        results, figures, notes = _run(args, Path(scratch))
    output = args.output or (None if args.quick else HERE)
    if output is not None:
        output.mkdir(parents=True, exist_ok=True)
        write_json(output / "results.json", results)
        (output / "results.md").write_text(markdown(results, figures, notes))
        print(f"wrote {output / 'results.json'} and {output / 'results.md'}")
    return 0


def _run(args: argparse.Namespace, scratch: Path) -> tuple[dict[str, Any], list[Figure], list[str]]:
    from benchmarks import fresh, in_process
    from benchmarks.references import own_robots, robosuite_installed, robosuite_robots

    started = time.perf_counter()
    quick = args.quick
    fresh_repeats = args.repeats or (1 if quick else 3)
    in_process_repeats = 3 if quick else 5
    robosuite = robosuite_robots() if robosuite_installed() else []
    own = own_robots()
    if quick:
        robosuite, own = [n for n in robosuite if n == "Panda"], [n for n in own if n == "Sparrow7"]
    if args.robots:
        chosen = set(args.robots.split(","))
        robosuite, own = [n for n in robosuite if n in chosen], [n for n in own if n in chosen]
    notes = [] if robosuite_installed() else ["robosuite is not installed: no robosuite comparisons"]
    figures: list[Figure] = []
    skipped: list[dict[str, str]] = []

    def record(new: Figure | list[Figure]) -> None:
        for figure in new if isinstance(new, list) else [new]:
            figures.append(figure)
            print(figure.line(), flush=True)

    for name in robosuite + own:
        is_robosuite = name in robosuite
        try:
            record(in_process.assemble(name, is_robosuite, in_process_repeats))
            record(fresh.cold_and_warm(name, is_robosuite, scratch, scratch / f"{name}.xml", fresh_repeats))
            record(in_process.repeated(name, in_process_repeats))
        except Exception as error:  # a robot that does not build on one side is reported, not fatal
            reason = f"{type(error).__name__}: {' '.join(str(error).split())[:200]}"
            skipped.append({"robot": name, "reason": reason})
            print(f"skipped {name}: {reason}", flush=True)
            if os.environ.get("BENCHMARK_DEBUG"):
                traceback.print_exc()
    counts = [1, 2, 4] if quick else [1, 2, 4, 8, 16, 32]
    scale_rows, scale_figure = fresh.scale(counts, fresh_repeats)
    record(scale_figure)
    record(fresh.startup(fresh_repeats if quick else 5))
    elapsed = time.perf_counter() - started
    notes.append(f"total run time {elapsed / 60:.1f} min")
    load = os.getloadavg()[1]
    if load > 0.5 * (os.cpu_count() or 1):
        notes.append(
            f"the CPUs were shared with other work during the run (5-minute load average {load:.1f} "
            f"on {os.cpu_count()} CPUs at the end): single figures are noisy, compare ratios"
        )
    results = {
        "machine": machine(),
        "settings": f"{fresh_repeats} per fresh-process figure, "
        f"{in_process_repeats} in-process (after 1 warm-up)",
        "figures": [figure.as_dict() for figure in figures],
        "scale": scale_rows,
        "skipped": skipped,
        "notes": notes,
    }
    return results, figures, notes
