"""The scale test's fresh process: ``python -m benchmarks.child scene N`` assembles and compiles a
scene of N robots in a new interpreter and prints the times and peak memory as one JSON line
(the other whole-process figures are in :mod:`benchmarks.whole`)."""

from __future__ import annotations

import json
import resource
import sys
import time
from collections.abc import Callable
from typing import Any


def _timed(action: Callable[[], Any]) -> tuple[Any, float]:
    start = time.perf_counter()
    result = action()
    return result, time.perf_counter() - start


def scene(count: str) -> dict[str, Any]:
    """A scene of ``count`` Sparrow7 robots with their gripper: assembly, compile, peak memory."""
    from benchmarks.references import scale_scene

    baseline = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    built, assemble = _timed(lambda: scale_scene(int(count)))
    _, compile_seconds = _timed(built.get_model)
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss
    scale = 1024 if sys.platform != "darwin" else 1  # kilobytes on Linux, bytes on macOS
    return {
        "assemble": assemble,
        "compile": compile_seconds,
        "peak_bytes": peak * scale,
        "added_bytes": (peak - baseline) * scale,
    }


MODES: dict[str, Callable[..., dict[str, Any]]] = {"scene": scene}

if __name__ == "__main__":
    print(json.dumps(MODES[sys.argv[1]](*sys.argv[2:])))
