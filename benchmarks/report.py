"""The benchmark's results as JSON and as a Markdown table, with the machine and the versions
they were measured on (figures from another machine are not comparable)."""

from __future__ import annotations

import json
import os
import platform
import subprocess
import time
from importlib import metadata
from pathlib import Path
from typing import Any

from benchmarks.figures import Figure, seconds_text
from benchmarks.timing import REPOSITORY


def _version(package: str) -> str:
    try:
        return metadata.version(package)
    except metadata.PackageNotFoundError:
        return "not installed"


def _cpu_model() -> str:
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown"


def _commit() -> str:
    try:
        result = subprocess.run(
            ["git", "rev-parse", "--short", "HEAD"],
            capture_output=True,
            text=True,
            cwd=REPOSITORY,
            timeout=10,
        )
        dirty = subprocess.run(
            ["git", "status", "--porcelain"], capture_output=True, text=True, cwd=REPOSITORY, timeout=30
        )
    except (OSError, subprocess.SubprocessError):
        return "unknown"
    return result.stdout.strip() + (" (with uncommitted changes)" if dirty.stdout.strip() else "")


def machine() -> dict[str, Any]:
    """Where and with what the benchmark ran."""
    return {
        "date": time.strftime("%Y-%m-%d %H:%M %Z"),
        "platform": platform.platform(),
        "cpu": _cpu_model(),
        "cpus": os.cpu_count(),
        "load_average_at_start": [round(x, 2) for x in os.getloadavg()],
        "python": platform.python_version(),
        "mujoco": _version("mujoco"),
        "robosuite": _version("robosuite"),
        "numpy": _version("numpy"),
        "robot-assembler": _version("robot-assembler"),
        "commit": _commit(),
    }


def write_json(path: Path, results: dict[str, Any]) -> None:
    """Everything, machine-readable."""
    path.write_text(json.dumps(results, indent=1) + "\n")


def _figure_rows(figures: list[Figure]) -> list[str]:
    rows = [
        "| measure | subject | ours | reference | ratio | target | met | note |",
        "|---|---|---|---|---|---|---|---|",
    ]
    for f in figures:
        met = "" if f.met is None else ("yes" if f.met else "**no**")
        rows.append(
            f"| {f.measure} | {f.subject} | {f.amount(f.ours)} "
            f"| {f.reference_name} {f.amount(f.reference)} "
            f"| {f.ratio:.2f}x | {f.target} | {met} | {f.note} |"
        )
    return rows


EXPLANATIONS = [
    "- Whole-process figures are wall times of a new Python process from spawn to exit, timed from",
    "  outside (start-up, imports, the work, and the exit, which waits for the cache entry's writer);",
    "  the notes give the in-process part (timed inside, after the snippet's imports) and the CPU ratio.",
    "- *1 uncached*: `import assembler; assemble(name).get_model()` with an empty model cache but every",
    "  mesh in the mesh store (a new variant, base or gripper, an edited spec), and with both empty",
    "  (first contact), against `import mujoco; MjModel.from_xml_path(robosuite's XML file)`.",
    "- *2 warm*: the cache holds the robot: `assembler.load_model(name)`, and `assemble(name)` followed by",
    "  `get_model()`, `get_xml()` or `save(file)` (all answered from the request record, no spec read),",
    "  against `import mujoco; MjModel.from_binary_path(entry)`; the rows marked *instructions* count",
    "  the instructions each whole process executes (valgrind's callgrind), which the load does not change.",
    "- *3 start-up*: `python -c 'import assembler'` minus `python -c 'import mujoco'`; `assembler --help`",
    "  minus `python -c pass` (absolute seconds against the target).",
    "- *4 get_xml*: warm in-process `assemble(name).get_xml()` against robosuite creating the robot and",
    "  calling `get_xml()`; `assembler build NAME -o FILE` warm against a process writing robosuite's XML;",
    "  a cold `get_xml` against a cold `get_model` (one compile of ours plus MuJoCo's XML writer).",
    "- *5 variants*: a new variant through the API (`get_model()`, and `get_xml()` with the robot's XML",
    "  cached), against MuJoCo compiling robosuite's XML; a sweep of joint damping values in one new",
    "  process per side, per variant; and `assembler variants --jobs 2` against `--jobs 1`.",
    "- *6*: scenes of N robots per robot, and the same robot loaded again in one process.",
    "- *environment* (target <= 1x): `robosuite.make` and hard `env.reset()` with robosuite's robot, gripper",
    "  and base built from our specs (`assembler.robosuite.replace_robosuite()`), against robosuite's own",
    "  classes, each side in new processes, our part files kept from an earlier process; the",
    "  whole-process figure is make plus five resets; each note gives the CPU-time ratio.",
]

REASONS: dict[str, str] = {
    "1 uncached": (
        "An uncached model needs the spec layer and a compile. The schema's validators are built on "
        "first use and their docstrings read only for the JSON Schema, and a cached answer imports "
        "neither; what is left for a first contact (the profile below): importing the model classes "
        "and the schema (pydantic itself and the classes it builds) and reading the robot's own "
        "specs (each shipped spec is read when its name is first looked up: three of the 63 for a "
        "Panda), then our compile with its mesh decode, and at exit the wait for the cache entry's "
        "writer (a Panda entry is 44 MB). MuJoCo's compile of robosuite's XML pays only the compile. "
        "With the meshes stored, our compile itself is at or below MuJoCo's (the in-process figures)."
    ),
    "2 warm": (
        "`assembler.load_model` and `assemble(name)` followed by `get_model()`, `get_xml()` or "
        "`save()` take the request-record path: no spec is read, no schema imported, neither the "
        "compile path nor the mesh store. What is left above the floor is about 50 modules of "
        "imports (the cache lookup, the record's checks, numpy.typing, json, xxhash), the check of "
        "the record's spec files and the XXH3 digest of the model file before MuJoCo reads it: about "
        "0.15 G instructions, which weigh most on small models, whose floor is mostly start-up."
    ),
    "5 variants": (
        "A variant that changes only patchable values (joints, actuators, friction, init_qpos) is the "
        "robot's XML, compiled once per process, with the values written in, and an API variant is "
        "patched onto the cached robot (its `get_xml()` the cached robot's XML with the values "
        "written in): both well below the references once the robot is compiled "
        "(the rows marked warm and robot cached). The row that misses carries our one compile of the "
        "robot, its spec layer and MuJoCo's XML writer in a short sweep; the whole-process API "
        "variant carries the spec layer's start-up (see 1 uncached), its patch is the in-process row."
    ),
    "5 variants jobs": (
        "Each worker process pays its own start-up, spec registration and first mesh decode before "
        "its first variant; with few variants per worker that fixed cost dominates."
    ),
    "6 scale": (
        "Assembling a scene costs more per robot as the scene grows (the assemble column): MuJoCo's "
        "own MjSpec.attach takes longer the larger the spec it attaches to (a Sparrow7 part: 0.3 ms "
        "into an empty spec, 3-4 ms into one of 64 robots, about 20 ms into one of 127, on MuJoCo "
        "3.9 and 4.0). Our check that no part's element is lost counts a scene's elements once, "
        "not after every robot (which cost N²: 8.5 s to assemble 64 robots, against 1.0 s now)."
    ),
    "environment": (
        "Our part files are kept across processes and a warm make writes and emits nothing, so "
        "`robosuite.make` is at or near robosuite's own; what is left is the bridge's registration "
        "at import (the schema, and every spec it installs: here all 63, as `replace_robosuite()` "
        "installs our specs of robosuite's 44 names, and robosuite's tables are plain dicts that need "
        "each name's class) and, per hard reset, "
        "robosuite parsing our assembly's file besides its own part file."
    ),
}
"""Why a measure misses its target, printed with the measure's profile when it does."""


def markdown(results: dict[str, Any], figures: list[Figure], notes: list[str]) -> str:
    """The report a reader checks the targets in."""
    m = results["machine"]
    lines = [
        "# Benchmark results",
        "",
        "Produced by `python -m benchmarks` (see the README's Performance section). Medians of interleaved",
        "runs; whole-process figures come from new processes, in-process ones from the harness (warmed up).",
        "",
        f"- Machine: {m['cpu']}, {m['cpus']} CPUs, {m['platform']}; "
        f"load average at start {m['load_average_at_start']}",
        f"- Versions: Python {m['python']}, MuJoCo {m['mujoco']}, robosuite {m['robosuite']}, "
        f"numpy {m['numpy']}, robot-assembler {m['robot-assembler']} at {m['commit']}",
        f"- Date: {m['date']}; repetitions: {results['settings']}",
        *[f"- {note}" for note in notes],
        "",
    ]
    by_measure: dict[str, list[Figure]] = {}
    for figure in figures:
        by_measure.setdefault(figure.measure, []).append(figure)
    lines += ["## Summary", "", "| measure | targets met |", "|---|---|"]
    for measure, group in by_measure.items():
        judged = [f for f in group if f.met is not None]
        if judged:
            lines.append(f"| {measure} | {sum(bool(f.met) for f in judged)} of {len(judged)} |")
    lines += ["", *EXPLANATIONS, ""]
    for measure, group in by_measure.items():
        lines += [f"## {measure}", "", *_figure_rows(group), ""]
    if results.get("scale"):
        lines += [
            "## scale: per N",
            "",
            "| robots | assemble / robot | compile / robot | total / robot | peak memory | added / robot |",
            "|---|---|---|---|---|---|",
        ]
        for row in results["scale"]:
            lines.append(
                f"| {row['robots']} | {seconds_text(row['assemble_per_robot'])} "
                f"| {seconds_text(row['compile_per_robot'])} | {seconds_text(row['total_per_robot'])} "
                f"| {row['peak_bytes'] / 2**20:.0f} MB "
                f"| {row['added_bytes_per_robot'] / 2**20:.1f} MB |"
            )
        lines.append("")
    missed = sorted({f.measure for f in figures if f.met is False})
    if missed:
        lines += ["## Missed targets: why", ""]
        for measure in missed:
            reason = REASONS.get(measure, "")
            if measure == "5 variants":
                missed_rows = [f for f in figures if f.measure == measure and f.met is False]
                reasons = [REASONS["5 variants"]] if any("jobs" not in f.subject for f in missed_rows) else []
                if any("jobs" in f.subject for f in missed_rows):
                    reasons.append(REASONS["5 variants jobs"])
                reason = " ".join(reasons)
            lines += [f"- *{measure}*: {reason}", ""]
        for title, table in results.get("profiles", {}).items():
            lines += [f"### Profile: {title}", "", "```text", table, "```", ""]
    if results.get("skipped"):
        lines += [
            "## skipped",
            "",
            *[f"- {item['robot']}: {item['reason']}" for item in results["skipped"]],
            "",
        ]
    return "\n".join(lines)
