"""Measurements made in the harness's own process, interleaved with warm-up: assembling MJCF text
(ours against robosuite's model layer, or against MuJoCo's parse of our XML for our own robots),
and loading a robot again in the same process (ours, from the cache, against MuJoCo's warm
recompile and against copying a model)."""

from __future__ import annotations

import copy
from collections.abc import Callable

import mujoco

import assembler
from assembler import cache
from assembler.mjcf.emit import to_xml
from benchmarks.figures import Figure, ratio_figure
from tests.parity.robosuite_side import robosuite_xml

ASSEMBLE_TARGET = 0.5
REPEATED_TARGET = 1.2


def _our_xml(name: str) -> str:
    return to_xml(assembler.assemble(name).mjspec)


def assemble(name: str, against_robosuite: bool, repeats: int) -> list[Figure]:
    """Spec to MJCF text, no compile: ours against robosuite's, or against MuJoCo parsing ours.

    Also ours up to the assembled ``MjSpec`` only: MuJoCo's XML writer (``MjSpec.to_xml``)
    compiles the spec inside, so for robots with meshes the text costs a (warm) compile.
    """
    reference: Callable[[], object]
    if against_robosuite:
        reference, reference_name = (lambda: robosuite_xml(name)), "robosuite"
    else:
        xml = _our_xml(name)
        reference, reference_name = (lambda: mujoco.MjSpec.from_string(xml)), "MuJoCo parse"
    cases = {
        "text": lambda: _our_xml(name),
        "spec": lambda: assembler.assemble(name).mjspec,
        "reference": reference,
    }
    times = interleaved_cases(cases, repeats)
    at_most = ASSEMBLE_TARGET if against_robosuite else None
    return [
        ratio_figure("assemble", name, times["text"], reference_name, times["reference"], at_most),
        ratio_figure(
            "assemble",
            f"{name} (MjSpec)",
            times["spec"],
            reference_name,
            times["reference"],
            at_most,
            "to our MjSpec, without MuJoCo's XML writer",
        ),
    ]


def repeated(name: str, repeats: int) -> list[Figure]:
    """The same robot loaded again in one process: ours (a cache hit) against MuJoCo recompiling
    the same XML with its asset cache warm, and against ``copy.copy`` of a model."""
    robot = assembler.assemble(name)
    model = robot.get_model()
    cache.wait_for_writes()
    xml = robot.get_xml()
    hits = cache.counts.hits
    times = interleaved_cases(
        {
            "ours": lambda: assembler.assemble(name).get_model(),
            "recompile": lambda: mujoco.MjModel.from_xml_string(xml),
            "copy": lambda: copy.copy(model),
        },
        repeats,
    )
    note = "" if cache.counts.hits > hits else "no cache hit: assembler code changed meanwhile?"
    return [
        ratio_figure(
            "repeated load",
            name,
            times["ours"],
            "MuJoCo recompile",
            times["recompile"],
            REPEATED_TARGET,
            note,
        ),
        ratio_figure(
            "repeated load", name, times["ours"], "model copy", times["copy"], REPEATED_TARGET, note
        ),
    ]


def interleaved_cases(cases: dict[str, Callable[[], object]], repeats: int) -> dict[str, float]:
    """:func:`benchmarks.timing.interleaved` with one warm-up round."""
    from benchmarks.timing import interleaved

    return interleaved(cases, repeats, warmup=1)
