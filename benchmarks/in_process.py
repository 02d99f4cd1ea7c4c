"""Measurements made in the harness's own process, interleaved after a warm-up: ``get_xml`` of a
robot the cache holds against robosuite's ``get_xml`` (target 4), and loading a robot again and
again in one process (target 6: from the in-memory copy, against MuJoCo's warm recompile and a
model copy)."""

from __future__ import annotations

import copy
from collections.abc import Callable

import mujoco

import assembler
from assembler.compiler import service
from benchmarks.figures import Figure, ratio_figure
from benchmarks.timing import interleaved

XML_TARGET = 2.0
REPEATED_TARGET = 1.2


def get_xml(name: str, robosuite: bool, repeats: int) -> list[Figure]:
    """``assemble(name).get_xml()`` with the XML in the cache, against robosuite creating the robot
    and calling its ``get_xml`` (our own robots: against MuJoCo parsing our XML; no target)."""
    xml = assembler.assemble(name).get_xml()
    service.wait_for_writes()
    reference: Callable[[], object]
    if robosuite:
        from tests.parity.robosuite_side import robosuite_xml

        reference, reference_name = (lambda: robosuite_xml(name)), "robosuite create + get_xml"
    else:
        reference, reference_name = (lambda: mujoco.MjSpec.from_string(xml)), "MuJoCo parse of our XML"
    hits = service.counts.hits
    times = interleaved({"ours": lambda: assembler.assemble(name).get_xml(), "reference": reference}, repeats)
    note = "from the cache" if service.counts.hits > hits else "NOT from the cache"
    target = XML_TARGET if robosuite else None
    return [
        ratio_figure(
            "4 get_xml", f"{name} warm", times["ours"], reference_name, times["reference"], target, note
        )
    ]


def repeated(name: str, repeats: int) -> list[Figure]:
    """The same robot loaded again in one process: ours (a cache hit) against MuJoCo recompiling
    the same XML with its asset cache warm, and against ``copy.copy`` of a model."""
    robot = assembler.assemble(name)
    model = robot.get_model()
    service.wait_for_writes()
    xml = robot.get_xml()
    hits = service.counts.hits
    times = interleaved(
        {
            "ours": lambda: assembler.assemble(name).get_model(),
            "recompile": lambda: mujoco.MjModel.from_xml_string(xml),
            "copy": lambda: copy.copy(model),
        },
        repeats,
    )
    note = "" if service.counts.hits > hits else "no cache hit: assembler code changed meanwhile?"
    return [
        ratio_figure(
            "6 repeated load",
            name,
            times["ours"],
            "MuJoCo recompile",
            times["recompile"],
            REPEATED_TARGET,
            note,
        ),
        ratio_figure("6 repeated load", name, times["ours"], "model copy", times["copy"], None, note),
    ]
