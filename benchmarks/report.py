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
            f"| {f.measure} | {f.subject} | {seconds_text(f.ours)} "
            f"| {f.reference_name} {seconds_text(f.reference)} "
            f"| {f.ratio:.2f}x | {f.target} | {met} | {f.note} |"
        )
    return rows


EXPLANATIONS = [
    "- *assemble*: spec to MJCF text. MuJoCo's XML writer (`MjSpec.to_xml`) compiles the spec inside,",
    "  so for robots with meshes the text costs a warm compile; the `(MjSpec)` rows stop at the",
    "  assembled `MjSpec`. Our own robots are compared with MuJoCo parsing our XML (no target).",
    "- *cold load*: `assemble(name).get_model()` in a new process with an empty cache, against MuJoCo",
    "  compiling the same robot's XML in a new process. Hashing the inputs and writing the cache",
    "  entry happen afterwards in a background thread (the note gives that time).",
    "- *warm load*: the same in a new process whose cache holds the robot, against robosuite's cold",
    "  load (a speed-up) and against `MjModel.from_binary_path` of the cached file (the floor).",
    "- *repeated load*: in one process, again and again (from the in-memory copy after the second",
    "  load), against MuJoCo recompiling the XML with its asset cache warm, and against `copy.copy`.",
]


def markdown(results: dict[str, Any], figures: list[Figure], notes: list[str]) -> str:
    """The report a reader checks the targets in."""
    m = results["machine"]
    lines = [
        "# Benchmark results",
        "",
        "Produced by `python -m benchmarks` (see the README's Performance section). Medians of interleaved",
        "repetitions after a warm-up; cold, warm, scale and start-up figures each come from fresh processes.",
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
    if results.get("skipped"):
        lines += [
            "## skipped",
            "",
            *[f"- {item['robot']}: {item['reason']}" for item in results["skipped"]],
            "",
        ]
    return "\n".join(lines)
