"""The mesh store measured in new processes: ``python -m benchmarks.mesh_store [ROBOT ...] [--repeats N]``.

For each robot (default Panda and GR1), interleaved, each run a new interpreter timed from outside
(whole process: start-up, imports, assembly, compile, exit; wall and CPU seconds, the latter less
sensitive to a busy machine) and from inside (the compile alone):

- ``mujoco``: MuJoCo compiling robosuite's own assembled XML, written to a file first (the reference);
- ``plain``: our assembly compiled from the mesh files (no store);
- ``warm``: our assembly with every mesh in the store (``use_stored_meshes``);
- ``records gone``: the same store without its path records, so every file is hashed again (the
  same meshes at a new path: another checkout or environment);
- ``first contact``: an empty store; the background filler it starts is timed on its own, and the
  next run waits for it, so runs do not overlap.

It prints medians and the ratios the issue sets: warm <= 0.5x and first contact <= 1.1x ``mujoco``.
The model cache plays no part: the children compile the spec themselves.
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Any

from benchmarks.timing import REPOSITORY, median


def child(mode: str, name: str, target: str) -> dict[str, Any]:
    """One measured process: ``target`` is the XML file (mujoco) or the store folder."""
    started = time.perf_counter()
    if mode == "mujoco":
        import mujoco

        imported = time.perf_counter()
        mujoco.MjModel.from_xml_path(target)
        return {"import": imported - started, "compile": time.perf_counter() - imported}
    import assembler
    from assembler.cache.mesh_swap import _fillers, use_stored_meshes
    from assembler.cache.meshes import MeshStore
    from assembler.mjcf.keyframe import compile_with_home

    imported = time.perf_counter()
    robot = assembler.assemble(name)
    spec = robot._new_assembly()
    assembled = time.perf_counter()
    if mode == "plain":
        compile_with_home(spec, robot.assembly_home(), robot._what())
        return {
            "import": imported - started,
            "assemble": assembled - imported,
            "compile": time.perf_counter() - assembled,
        }
    with use_stored_meshes(spec, MeshStore(Path(target), 1 << 31)) as swap:
        looked_up = time.perf_counter()
        compile_with_home(spec, robot.assembly_home(), robot._what())
        compiled = time.perf_counter()
    return {
        "import": imported - started,
        "assemble": assembled - imported,
        "lookup": looked_up - assembled,
        "compile": compiled - looked_up,
        "stored": len(swap.stored),
        "missing": len(swap.missing),
        "filler": _fillers[0].pid if _fillers else 0,
    }


def _alive(pid: int) -> bool:
    try:
        with open(f"/proc/{pid}/stat") as stat:
            return stat.read().split(")")[-1].split()[0] != "Z"
    except OSError:
        return False


def _run(mode: str, name: str, target: str) -> dict[str, Any]:
    """A new interpreter for ``child``: its JSON plus the whole process's wall time."""
    environment = {**os.environ, "PYTHONPATH": str(REPOSITORY)}
    command = [sys.executable, "-m", "benchmarks.mesh_store", "child", mode, name, target]
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    result = subprocess.run(command, capture_output=True, text=True, cwd=REPOSITORY, env=environment)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    lines = [line for line in result.stdout.splitlines() if line.startswith("{")]
    if result.returncode or not lines:
        raise RuntimeError(f"{mode} {name}: {(result.stderr.strip().splitlines() or ['no output'])[-1]}")
    figures: dict[str, Any] = {**json.loads(lines[-1]), "process": wall, "cpu": cpu}
    if figures.get("filler"):
        while _alive(figures["filler"]):  # the filler outlives the process: wait before the next run
            time.sleep(0.02)
        figures["filler"] = time.perf_counter() - start - wall
    return figures


def measure(name: str, repeats: int, scratch: Path) -> dict[str, dict[str, float]]:
    """Median figures of each mode for one robot."""
    from tests.robosuite_reference import robosuite_xml

    xml = scratch / f"{name}.xml"
    xml.write_text(robosuite_xml(name))
    warm = scratch / f"{name}-warm"
    _run("store", name, str(warm))  # fills the warm store (and waits for its filler)
    runs: dict[str, list[dict[str, Any]]] = {}
    for index in range(repeats):
        cold = scratch / f"{name}-first-{index}"
        bare = scratch / f"{name}-bare-{index}"
        subprocess.run(["cp", "-r", str(warm), str(bare)], check=True)
        for record in bare.glob("*.src"):
            record.unlink()
        modes = [("mujoco", str(xml)), ("plain", ""), ("warm", str(warm)), ("records gone", str(bare))]
        modes.append(("first contact", str(cold)))
        for mode, target in modes if index % 2 == 0 else modes[::-1]:
            kind = "store" if mode in ("warm", "records gone", "first contact") else mode
            runs.setdefault(mode, []).append(_run(kind, name, target))
    return {
        mode: {key: median([float(run[key]) for run in results]) for key in results[0]}
        for mode, results in runs.items()
    }


def report(name: str, figures: dict[str, dict[str, float]]) -> None:
    reference = figures["mujoco"]
    print(f"\n{name}: medians, seconds; ratios against MuJoCo compiling robosuite's XML in a new process")
    for mode, values in figures.items():
        ratio = values["process"] / reference["process"]
        cpu = values["cpu"] / reference["cpu"]
        parts = ", ".join(
            f"{key} {value:.3f}" for key, value in values.items() if key not in ("process", "cpu")
        )
        wall = f"wall {values['process']:.3f} ({ratio:.2f}x)"
        print(f"  {mode:14s} {wall} cpu {values['cpu']:.3f} ({cpu:.2f}x)  [{parts}]")
    for figure in ("process", "cpu"):
        warm = figures["warm"][figure] / reference[figure]
        first = figures["first contact"][figure] / reference[figure]
        print(f"  targets ({figure}): warm {warm:.2f}x (<= 0.5x), first contact {first:.2f}x (<= 1.1x)")


def main(argv: list[str]) -> int:
    if argv[:1] == ["child"]:
        mode, name, target = argv[1:4]
        print(json.dumps(child(mode, name, target)))
        return 0
    parser = argparse.ArgumentParser(
        prog="python -m benchmarks.mesh_store", description=__doc__.split("\n\n")[0]
    )
    parser.add_argument("robots", nargs="*", default=["Panda", "GR1"])
    parser.add_argument("--repeats", type=int, default=5)
    args = parser.parse_args(argv)
    with tempfile.TemporaryDirectory(prefix="assembler-meshes-") as scratch:
        for name in args.robots:
            report(name, measure(name, args.repeats, Path(scratch)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
