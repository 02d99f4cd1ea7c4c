"""The benchmark harness: ``python -m benchmarks [--quick] [--output DIR] [--robots A,B]``.

It measures, and prints as ratios against their references, the issue's six targets, whole
processes beside in-process parts: (1) a model not cached whose meshes were seen, and first
contact, against MuJoCo compiling robosuite's XML; (2) a cached model against the ``.mjb`` floor;
(3) start-up; (4) ``get_xml`` and ``build -o``; (5) variants and ``--jobs``; (6) scale and repeated
load; and robosuite environments with robots from our specs against robosuite's classes. Every robot
of ``specs/robosuite/robots`` is measured for (1) and (2) (robots that fail to
build on either side are reported and skipped), our own robots for (2). The caches used are
temporary folders, never the user's. A full run writes ``benchmarks/results.json`` and
``benchmarks/results.md``; ``--quick`` (a smoke run on Panda when robosuite is installed, and
Sparrow7) writes only where ``--output`` says.
"""

from __future__ import annotations

import argparse
import os
import tempfile
import time
import traceback
from collections.abc import Callable
from pathlib import Path
from typing import Any

from benchmarks.figures import Figure
from benchmarks.processes import compile_bytecode
from benchmarks.report import machine, markdown, write_json

HERE = Path(__file__).resolve().parent

XML_ROBOTS = ("Panda", "GR1")
"""Robots of the get_xml, variants and repeated-load measures (the issue's examples)."""


def _arguments(argv: list[str] | None) -> argparse.Namespace:
    parser = argparse.ArgumentParser(prog="python -m benchmarks", description=__doc__.split("\n\n")[0])
    parser.add_argument("--quick", action="store_true", help="smoke run: few robots, one repetition")
    parser.add_argument("--output", type=Path, help="folder for results.json and results.md")
    parser.add_argument("--robots", help="comma-separated robot names instead of all")
    parser.add_argument("--repeats", type=int, help="fresh-process repetitions (default 3; quick: 1)")
    return parser.parse_args(argv)


def main(argv: list[str] | None = None) -> int:
    args = _arguments(argv)
    compile_bytecode()
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
    from benchmarks import environments, fresh, in_process, instructions, variants, whole
    from benchmarks.references import own_robots, robosuite_installed, robosuite_robots
    from tests.parity.robosuite_side import robosuite_xml

    started = time.perf_counter()
    quick = args.quick
    repeats = args.repeats or (1 if quick else 3)
    in_process_repeats = 3 if quick else 5
    robosuite = robosuite_robots() if robosuite_installed() else []
    own = own_robots()
    if quick:
        robosuite, own = [n for n in robosuite if n == "Panda"], [n for n in own if n == "Sparrow7"]
    if args.robots:
        chosen = set(args.robots.split(","))
        robosuite, own = [n for n in robosuite if n in chosen], [n for n in own if n in chosen]
    notes = [] if robosuite_installed() else ["robosuite is not installed: no robosuite comparisons"]
    if os.environ.get("PYTHONDONTWRITEBYTECODE"):
        notes.append("PYTHONDONTWRITEBYTECODE is set: the repository's bytecode was compiled before the run")
    figures: list[Figure] = []
    skipped: list[dict[str, str]] = []

    def record(new: Figure | list[Figure]) -> None:
        for figure in new if isinstance(new, list) else [new]:
            figures.append(figure)
            print(figure.line(), flush=True)

    def guarded(name: str, measure: Callable[[], list[Figure]]) -> None:
        try:
            record(measure())
        except Exception as error:  # a robot that does not build on one side is reported, not fatal
            reason = f"{type(error).__name__}: {' '.join(str(error).split())[:200]}"
            skipped.append({"robot": name, "reason": reason})
            print(f"skipped {name}: {reason}", flush=True)
            if os.environ.get("BENCHMARK_DEBUG"):
                traceback.print_exc()

    record(whole.startup(repeats if quick else 5))

    def robosuite_robot(name: str) -> list[Figure]:
        xml_file = scratch / f"{name}-robosuite.xml"
        xml_file.write_text(robosuite_xml(name))
        return [*whole.uncached(name, xml_file, scratch, repeats), *whole.warm(name, scratch, repeats, True)]

    def xml_figures(name: str) -> list[Figure]:
        in_process_figures = in_process.get_xml(name, bool(robosuite), in_process_repeats)
        return [*in_process_figures, *(whole.xml_whole(name, scratch, repeats) if robosuite else [])]

    def variant_figures(name: str) -> list[Figure]:
        count = 4 if quick else 16
        per_variant = variants.per_variant(name, count, scratch, repeats)
        patched = variants.patched_variant(name, scratch / f"{name}-robosuite.xml", scratch, repeats)
        return [*patched, *per_variant, *variants.jobs(name, count, scratch, repeats)]

    for name in robosuite:
        guarded(name, lambda name=name: robosuite_robot(name))
    for name in own:
        guarded(name, lambda name=name: whole.warm(name, scratch, repeats, False))
    xml_robots = [n for n in robosuite if n in XML_ROBOTS] or own[:1]
    if not quick and xml_robots and instructions.available():  # the warm figures, load-independent
        counted = xml_robots[0]
        guarded(counted, lambda: instructions.warm(counted, whole.warm_cache(counted, scratch)))
    for name in xml_robots:
        guarded(name, lambda name=name: xml_figures(name))
    if robosuite:
        guarded(xml_robots[0], lambda: variant_figures(xml_robots[0]))
    for name in dict.fromkeys(xml_robots + own[:1]):
        guarded(name, lambda name=name: in_process.repeated(name, in_process_repeats))
    if robosuite:
        guarded("environments", lambda: environments.environment_figures(repeats))
    counts = [1, 2, 4] if quick else [1, 2, 4, 8, 16, 32, 64]
    scale_rows, scale_figure = fresh.scale(counts, repeats)
    record(scale_figure)
    found = {} if quick else _profiles(figures, xml_robots[0] if robosuite else None, scratch)
    elapsed = time.perf_counter() - started
    notes.append(f"total run time {elapsed / 60:.1f} min")
    load = os.getloadavg()
    notes.append(
        f"load average at the end {load[0]:.1f} / {load[1]:.1f} / {load[2]:.1f} (1, 5, 15 min) on "
        f"{os.cpu_count()} CPUs: other work shared the machine, so single figures are noisy; "
        "each figure is a median of interleaved runs"
    )
    results = {
        "machine": machine(),
        "settings": f"{repeats} per whole-process figure, {in_process_repeats} in-process (after 1 warm-up)",
        "figures": [figure.as_dict() for figure in figures],
        "scale": scale_rows,
        "skipped": skipped,
        "notes": notes,
        "profiles": found,
    }
    return results, figures, notes


def _profiles(figures: list[Figure], robot: str | None, scratch: Path) -> dict[str, str]:
    """cProfile tables of the measures that missed their target (see :mod:`benchmarks.profiles`)."""
    from benchmarks import profiles

    missed = {figure.measure for figure in figures if figure.met is False}
    found: dict[str, str] = {}
    if robot is not None and "1 uncached" in missed:
        found[f"1 uncached: {robot}, import assembler + assemble().get_model(), meshes stored"] = (
            profiles.uncached(robot, scratch)
        )
    if robot is not None and "5 variants" in missed:
        found[f"5 variants: {robot}, 16 variants, one job, by own time"] = profiles.variants(
            robot, 16, scratch
        )
    return found
