"""The fresh-process side of the benchmarks: ``python -m benchmarks.child MODE ARGS`` measures one
thing in a new interpreter and prints it as one JSON line.

Only the standard library is imported before timing starts, so start-up figures are honest.
Imports of mujoco, assembler and robosuite are excluded from every other figure (start-up is
measured on its own).
"""

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


def startup_mujoco() -> dict[str, Any]:
    """``import mujoco`` alone."""
    _, seconds = _timed(lambda: __import__("mujoco"))
    return {"import": seconds}


def startup_assembler() -> dict[str, Any]:
    """``import assembler``, which imports mujoco and registers every shipped spec."""
    assembler, seconds = _timed(lambda: __import__("assembler"))
    return {"import": seconds, "robots": len(assembler.REGISTERED_ROBOTS)}


def ours_cold(name: str) -> dict[str, Any]:
    """Spec to MjModel in a new process with an empty cache (the entry is written meanwhile)."""
    import assembler
    import assembler.cache

    robot, create = _timed(lambda: assembler.assemble(name))
    _, compile_seconds = _timed(robot.get_model)
    _, write = _timed(assembler.cache.wait_for_writes)
    counts = assembler.cache.counts
    return {
        "create": create,
        "get_model": compile_seconds,
        "total": create + compile_seconds,
        "write": write,
        "misses": counts.misses,
    }


def _entry_model_file(robot: Any) -> str | None:
    """The cached model file of ``robot``, if the cache has it (a concurrent edit of the
    assembler's code changes every key: then there is none, and the harness runs again)."""
    from assembler.cache import default_store
    from assembler.cache.key import cache_key

    store = default_store()
    entry = store._read_entry(cache_key(robot.build_inputs()) or "")
    return None if entry is None else str(store.directory / entry.model)


def ours_warm(name: str, floor_first: str) -> dict[str, Any]:
    """Spec to MjModel in a new process whose cache holds the robot; and MuJoCo loading that
    cached binary model directly (the floor), in the order given."""
    import mujoco

    import assembler
    import assembler.cache

    def ours() -> tuple[float, float]:
        robot, create = _timed(lambda: assembler.assemble(name))
        _, load = _timed(robot.get_model)
        return create, load

    def floor() -> float:
        path = _entry_model_file(assembler.assemble(name))
        return float("nan") if path is None else _timed(lambda: mujoco.MjModel.from_binary_path(path))[1]

    if floor_first == "1":
        floor_seconds = floor()
        create, load = ours()
    else:
        create, load = ours()
        floor_seconds = floor()
    return {
        "create": create,
        "get_model": load,
        "total": create + load,
        "floor": floor_seconds,
        "hits": assembler.cache.counts.hits,
    }


def robosuite_cold(name: str) -> dict[str, Any]:
    """robosuite's load of a robot in a new process: assemble its XML, then MuJoCo compiles it."""
    import mujoco

    from tests.parity.robosuite_side import robosuite_xml

    xml, assemble = _timed(lambda: robosuite_xml(name))
    _, compile_seconds = _timed(lambda: mujoco.MjModel.from_xml_string(xml))
    return {"assemble": assemble, "compile": compile_seconds, "total": assemble + compile_seconds}


def xml_compile(path: str) -> dict[str, Any]:
    """MuJoCo compiling an XML file in a new process."""
    import mujoco

    return {"compile": _timed(lambda: mujoco.MjModel.from_xml_path(path))[1]}


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


MODES: dict[str, Callable[..., dict[str, Any]]] = {
    "startup-mujoco": startup_mujoco,
    "startup-assembler": startup_assembler,
    "ours-cold": ours_cold,
    "ours-warm": ours_warm,
    "robosuite-cold": robosuite_cold,
    "xml-compile": xml_compile,
    "scene": scene,
}

if __name__ == "__main__":
    print(json.dumps(MODES[sys.argv[1]](*sys.argv[2:])))
