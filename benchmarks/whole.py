"""The issue's whole-process targets, each run in new processes, interleaved, medians:

1. a model not in the cache whose meshes were seen before (and first contact with the meshes)
   against MuJoCo compiling robosuite's own XML file in a new process;
2. a model in the cache, loaded by ``assembler.load_model`` (and by ``assemble().get_model()``),
   against the floor: a new process that imports mujoco and loads the cached ``.mjb``;
3. start-up: ``import assembler`` against ``import mujoco``, ``assembler --help`` against Python;
4. ``assembler build -o`` warm against robosuite writing its XML, and a cold ``get_xml`` against a
   cold ``get_model`` (one compile, not two).
"""

from __future__ import annotations

import shutil
import subprocess
import sys
from collections.abc import Callable
from pathlib import Path

from benchmarks.figures import Figure, ratio_figure, seconds_text
from benchmarks.processes import Run, medians, run_command, run_python, wait_for_process

UNCACHED_TARGET = 0.5
FIRST_CONTACT_TARGET = 1.1
WARM_FLOOR_TARGET = 1.2
IMPORT_TARGET = 0.15
HELP_TARGET = 0.1
XML_TARGET = 2.0

ASSEMBLER = str(Path(sys.executable).parent / "assembler")

_FILLERS = "from assembler.cache.mesh_swap import _fillers"
_NOTE_FILLERS = 'out["fillers"] = [p.pid for p in _fillers]'


def _interleave(cases: dict[str, Callable[[int], Run]], repeats: int) -> dict[str, Run]:
    runs: dict[str, list[Run]] = {name: [] for name in cases}
    for index in range(repeats):
        for name in list(cases) if index % 2 == 0 else list(cases)[::-1]:
            runs[name].append(cases[name](index))
    return {name: medians(results) for name, results in runs.items()}


def _cache(folder: Path, meshes_from: Path | None = None) -> dict[str, str]:
    """A new cache folder (with a hard-linked copy of a filled mesh store, when given)."""
    shutil.rmtree(folder, ignore_errors=True)
    folder.mkdir(parents=True)
    if meshes_from is not None and (meshes_from / "meshes").is_dir():
        subprocess.run(["cp", "-al", str(meshes_from / "meshes"), str(folder / "meshes")], check=True)
    return {"ASSEMBLER_CACHE_DIR": str(folder)}


def _get_model(name: str, env: dict[str, str]) -> Run:
    """``assemble(name).get_model()`` in a new process, waiting for the mesh filler it starts."""
    run = run_python(
        f"import assembler\n{_FILLERS}", f"assembler.assemble({name!r}).get_model()\n{_NOTE_FILLERS}", env
    )
    for pid in run.inner.get("fillers", []):
        wait_for_process(int(pid))
    return run


def uncached(name: str, xml_file: Path, scratch: Path, repeats: int) -> list[Figure]:
    """Target 1: ours (meshes stored, model not cached; and first contact) against MuJoCo compiling
    robosuite's XML file, each in a new process."""
    filled = scratch / f"meshes-{name}"
    _get_model(name, _cache(filled))  # the first contact fills this mesh store
    results = _interleave(
        {
            "mujoco": lambda i: run_python(
                "import mujoco", f"mujoco.MjModel.from_xml_path({str(xml_file)!r})"
            ),
            "stored": lambda i: _get_model(name, _cache(scratch / f"u-{name}-{i}", filled)),
            "first": lambda i: _get_model(name, _cache(scratch / f"f-{name}-{i}")),
        },
        repeats,
    )
    reference, stored, first = results["mujoco"], results["stored"], results["first"]

    def note(run: Run) -> str:
        return (
            f"in-process {seconds_text(run.inner['inside'])} vs {seconds_text(reference.inner['inside'])} "
            f"({run.inner['inside'] / reference.inner['inside']:.2f}x); CPU {run.cpu / reference.cpu:.2f}x"
        )

    mujoco = "MuJoCo compile (robosuite XML), whole process"
    return [
        ratio_figure("1 uncached", name, stored.wall, mujoco, reference.wall, UNCACHED_TARGET, note(stored)),
        ratio_figure(
            "1 uncached",
            f"{name} first contact",
            first.wall,
            mujoco,
            reference.wall,
            FIRST_CONTACT_TARGET,
            note(first),
        ),
    ]


def warm_cache(name: str, scratch: Path) -> dict[str, str]:
    """The environment of a cache that holds ``name`` (made by :func:`warm`)."""
    return {"ASSEMBLER_CACHE_DIR": str(scratch / f"w-{name}")}


def entry_path(name: str, env: dict[str, str]) -> str:
    """The ``.mjb`` file of the cache entry that holds ``name`` in the cache ``env`` names."""
    return str(
        run_python(
            "import assembler\nfrom assembler.compiler.service import default_store\n"
            "from assembler.cache.key import cache_key\nfrom assembler.registry import instances",
            f"s = default_store(); e = s.entry(cache_key(instances.assemble({name!r}).build_inputs()))\n"
            'out["path"] = str(s.directory / e.model)',
            env,
        ).inner["path"]
    )


def warm(name: str, scratch: Path, repeats: int, robosuite: bool) -> list[Figure]:
    """Target 2: a new process loading a cached robot, against the ``.mjb`` floor; and how much
    faster than robosuite's cold load that is (no target: it follows from the floor)."""
    env = _cache(Path(warm_cache(name, scratch)["ASSEMBLER_CACHE_DIR"]))
    # compiles, records the request, stores the model and its XML
    run_python("import assembler", f"r = assembler.assemble({name!r}); r.get_model(); r.get_xml()", env)
    entry = entry_path(name, env)
    out = str(scratch / f"{name}-saved.xml")
    cases: dict[str, Callable[[int], Run]] = {
        "floor": lambda i: run_python("import mujoco", f"mujoco.MjModel.from_binary_path({entry!r})", env),
        "load_model": lambda i: run_python("import assembler", f"assembler.load_model({name!r})", env),
        "get_model": lambda i: run_python(
            "import assembler", f"assembler.assemble({name!r}).get_model()", env
        ),
        "get_xml": lambda i: run_python("import assembler", f"assembler.assemble({name!r}).get_xml()", env),
        "save": lambda i: run_python("import assembler", f"assembler.assemble({name!r}).save({out!r})", env),
    }
    if robosuite:
        cases["robosuite"] = lambda i: run_python(
            "from tests.parity.robosuite_side import robosuite_model", f"robosuite_model({name!r})"
        )
    results = _interleave(cases, repeats)
    floor = results["floor"]

    def note(run: Run) -> str:
        inside = f"in-process {seconds_text(run.inner['inside'])} vs {seconds_text(floor.inner['inside'])}"
        return f"{inside}; CPU {run.cpu / floor.cpu:.2f}x"

    floor_name = "MuJoCo .mjb load, whole process"
    figures = [
        ratio_figure(
            "2 warm",
            f"{name} load_model",
            results["load_model"].wall,
            floor_name,
            floor.wall,
            WARM_FLOOR_TARGET,
            note(results["load_model"]),
        ),
        ratio_figure(
            "2 warm",
            f"{name} assemble().get_model()",
            results["get_model"].wall,
            floor_name,
            floor.wall,
            WARM_FLOOR_TARGET,
            note(results["get_model"]),
        ),
    ]
    figures += [
        ratio_figure(
            "2 warm",
            f"{name} assemble().{call}",
            results[case].wall,
            floor_name,
            floor.wall,
            WARM_FLOOR_TARGET,
            note(results[case]),
        )
        for case, call in (("get_xml", "get_xml()"), ("save", "save(file)"))
    ]
    if robosuite:
        speedup = results["robosuite"].wall / results["load_model"].wall
        figures.append(
            ratio_figure(
                "2 warm",
                f"{name} vs robosuite",
                results["load_model"].wall,
                "robosuite cold load, whole process",
                results["robosuite"].wall,
                None,
                f"load_model is {speedup:.1f}x faster than robosuite's cold load",
            )
        )
    return figures


def startup(repeats: int) -> list[Figure]:
    """Target 3: what ``import assembler`` adds to ``import mujoco``, and ``assembler --help`` to
    Python's own start-up (whole processes)."""
    results = _interleave(
        {
            "python": lambda i: run_python("", "pass"),
            "mujoco": lambda i: run_python("", "import mujoco"),
            "assembler": lambda i: run_python("", "import assembler"),
            "help": lambda i: run_command([ASSEMBLER, "--help"]),
        },
        repeats,
    )
    python, mujoco, assembler, help_ = (results[k].wall for k in ("python", "mujoco", "assembler", "help"))
    return [
        ratio_figure(
            "3 start-up",
            "import assembler, above import mujoco",
            assembler - mujoco,
            "target",
            IMPORT_TARGET,
            1.0,
            f"import assembler {seconds_text(assembler)}, import mujoco {seconds_text(mujoco)} "
            "(whole processes)",
        ),
        ratio_figure(
            "3 start-up",
            "assembler --help, above python",
            help_ - python,
            "target",
            HELP_TARGET,
            1.0,
            f"assembler --help {seconds_text(help_)}, python -c pass {seconds_text(python)}",
        ),
    ]


def xml_whole(name: str, scratch: Path, repeats: int) -> list[Figure]:
    """Target 4, whole process: ``assembler build NAME -o FILE`` with the cache warm against
    robosuite writing the same robot's XML; and a cold ``get_xml`` against a cold ``get_model``
    (meshes stored, model not cached): the XML costs one compile, not two."""
    env = _cache(scratch / f"x-{name}")
    out = scratch / f"{name}-built.xml"
    run_command([ASSEMBLER, "build", name, "-o", str(out)], env)  # compiles, records
    filled = scratch / f"meshes-{name}"
    results = _interleave(
        {
            "ours": lambda i: run_command([ASSEMBLER, "build", name, "-o", str(out)], env),
            "robosuite": lambda i: run_python(
                "from tests.parity.robosuite_side import robosuite_xml\nimport pathlib",
                f"pathlib.Path({str(scratch / 'rs.xml')!r}).write_text(robosuite_xml({name!r}))",
            ),
            "cold_xml": lambda i: run_python(
                "import assembler",
                f"assembler.assemble({name!r}).get_xml()",
                _cache(scratch / f"cx-{i}", filled),
            ),
            "cold_model": lambda i: run_python(
                "import assembler",
                f"assembler.assemble({name!r}).get_model()",
                _cache(scratch / f"cm-{i}", filled),
            ),
        },
        repeats,
    )
    cold_xml, cold_model = results["cold_xml"].inner["inside"], results["cold_model"].inner["inside"]
    return [
        ratio_figure(
            "4 get_xml",
            f"{name} build -o (whole process)",
            results["ours"].wall,
            "robosuite get_xml to a file, whole process",
            results["robosuite"].wall,
            XML_TARGET,
        ),
        ratio_figure(
            "4 get_xml",
            f"{name} cold get_xml",
            cold_xml,
            "cold get_model",
            cold_model,
            None,
            "in-process, meshes stored: one build, one compile, then MuJoCo's XML writer (it compiles again)",
        ),
    ]
