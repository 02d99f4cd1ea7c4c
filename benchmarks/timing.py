"""Timing helpers: interleaved repetitions with warm-up, medians, and measurements made in fresh
Python processes (for anything "cold": start-up, first compile, first load from the cache).

Interleaving (A, B, A, B, ... rather than A, A, ..., B, B, ...) spreads slow phases of a shared
machine over both sides of a comparison, and the median ignores the odd outlier.
"""

from __future__ import annotations

import json
import os
import statistics
import subprocess
import sys
import time
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

REPOSITORY = Path(__file__).resolve().parent.parent


def median(values: list[float]) -> float:
    """The median, or NaN for no values."""
    return statistics.median(values) if values else float("nan")


def interleaved(cases: Mapping[str, Callable[[], object]], repeats: int, warmup: int = 1) -> dict[str, float]:
    """Median seconds of each case, the cases run in turn, after ``warmup`` untimed rounds."""
    times: dict[str, list[float]] = {name: [] for name in cases}
    for round_index in range(warmup + repeats):
        names = list(cases)
        if round_index % 2:  # alternate the order too, so neither side always runs first
            names.reverse()
        for name in names:
            start = time.perf_counter()
            cases[name]()
            elapsed = time.perf_counter() - start
            if round_index >= warmup:
                times[name].append(elapsed)
    return {name: median(values) for name, values in times.items()}


def in_fresh_process(mode: str, *args: str, env: Mapping[str, str] | None = None) -> dict[str, Any]:
    """Run ``benchmarks.child`` in a new interpreter and return the JSON it prints last."""
    environment = {**os.environ, **(env or {})}
    environment["PYTHONPATH"] = os.pathsep.join(
        filter(None, [str(REPOSITORY), environment.get("PYTHONPATH")])
    )
    result = subprocess.run(
        [sys.executable, "-m", "benchmarks.child", mode, *args],
        capture_output=True,
        text=True,
        cwd=REPOSITORY,
        env=environment,
        timeout=600,
    )
    lines = [line for line in result.stdout.splitlines() if line.startswith("{")]
    if result.returncode != 0 or not lines:
        last = (result.stderr.strip().splitlines() or ["no output"])[-1]
        raise RuntimeError(f"{mode} {' '.join(args)}: {last}")
    return json.loads(lines[-1])  # type: ignore[no-any-return]


def fresh_medians(
    cases: Mapping[str, Callable[[int], dict[str, Any]]], repeats: int
) -> dict[str, dict[str, float]]:
    """Each case's JSON figures, medians over ``repeats`` interleaved runs (each run gets its index)."""
    runs: dict[str, list[dict[str, Any]]] = {name: [] for name in cases}
    for index in range(repeats):
        names = list(cases) if index % 2 == 0 else list(cases)[::-1]
        for name in names:
            runs[name].append(cases[name](index))
    return {
        name: {key: median([float(run[key]) for run in results]) for key in results[0]}
        for name, results in runs.items()
    }
