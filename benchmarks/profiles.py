"""Profiles for the report: where the time goes in a measure that missed its target, from cProfile
in a new process (the same work the measure times), trimmed to the lines that matter.

Each profile runs in the same kind of process the measure uses (a new interpreter, its own cache
folder with the mesh store filled where the measure has it), so its lines explain that figure.
"""

from __future__ import annotations

from pathlib import Path

from benchmarks.processes import run_python
from benchmarks.whole import _cache

_PROFILED = """\
import cProfile, io, pstats
profile = cProfile.Profile()
profile.enable()
{work}
profile.disable()
text = io.StringIO()
pstats.Stats(profile, stream=text).sort_stats({order!r}).print_stats({lines})
out["profile"] = text.getvalue()
"""


def _trimmed(text: str, keep: int) -> str:
    """The table of a pstats printout, first ``keep`` rows, paths shortened to the package."""
    lines = text.splitlines()
    start = next((i for i, line in enumerate(lines) if line.lstrip().startswith("ncalls")), 0)
    rows = [line for line in lines[start : start + keep + 1] if line.strip()]
    shortened = []
    for row in rows:
        for marker in ("/assembler/", "/site-packages/", "/lib/python3"):
            if marker in row:
                head, _, tail = row.partition(row[row.index("/") : row.index(marker)])
                row = head + "..." + tail
                break
        shortened.append(row)
    return "\n".join(shortened)


def profile(work: str, env: dict[str, str], order: str = "cumulative", keep: int = 22) -> str:
    """cProfile's table of ``work`` (Python statements) in a new process."""
    run = run_python("", _PROFILED.format(work=work, order=order, lines=keep * 2), env)
    return _trimmed(str(run.inner["profile"]), keep)


def uncached(name: str, scratch: Path) -> str:
    """``import assembler; assemble(name).get_model()``: meshes stored, model not cached."""
    env = _cache(scratch / f"p-{name}", scratch / f"meshes-{name}")
    return profile(f"import assembler\nassembler.assemble({name!r}).get_model()", env)


def variants(name: str, count: int, scratch: Path) -> str:
    """``write_variants`` of ``count`` variants with one job, by time spent in each function."""
    values = ",".join(str(round(0.05 + 0.01 * index, 4)) for index in range(count))
    env = _cache(scratch / f"pv-{name}", scratch / f"meshes-{name}")
    work = (
        "from assembler.worlds.variants import Grid, VariantPlan, write_variants\n"
        f"grid = Grid.parse('joint_defaults.damping={values}')\n"
        f"plan = VariantPlan(robot={name!r}, grids=(grid,), jobs=1)\n"
        f"write_variants(plan, {str(scratch / f'pv-{name}-out')!r})"
    )
    return profile(work, env, order="tottime", keep=14)
