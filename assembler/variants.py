"""Variants of one robot: a grid of override values and seeded random draws, built in parallel.

Variant ``i`` is the robot with its grid point's values and, for ``--random N``, values drawn
from ``numpy.random.default_rng([seed, i])``: they depend on the seed and the index only, so a
run is reproducible whatever the number of worker processes. Every variant is compiled before
its file is written (atomically); ``manifest.jsonl`` lists the written ones (index, file,
sha256, overrides). A variant that fails is reported with its overrides while the others are
still written: in a sweep of a thousand draws, one sample outside a field's range should not
cost the other 999 compiled models, and the exit code still says the sweep is incomplete.
"""

from __future__ import annotations

import hashlib
import itertools
import json
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any, Literal

import numpy as np
import yaml

from assembler.assembly import DEFAULT, assemble
from assembler.catalog import check_override_paths, register_specs, with_overrides
from assembler.documents import Override, parse_overrides, parse_path
from assembler.errors import AssemblerError, Problem
from assembler.registry import robot_class
from assembler.writing import make_folder, write_atomically

MANIFEST = "manifest.jsonl"


def _flag_error(flag: str, text: str, expected: str) -> AssemblerError:
    return AssemblerError(f"--{flag} expects {expected}, got '{text}'")


@dataclass(frozen=True)
class Grid:
    """Every value of one field: ``joint_defaults.damping=0.05,0.1,0.2``."""

    key: str
    values: tuple[Any, ...]

    @classmethod
    def parse(cls, text: str) -> Grid:
        """``PATH=V1,V2,...``; values are YAML, so ``[0.1, 0.2],[0.3, 0.4]`` gives two lists."""
        key, _, raw = text.partition("=")
        try:
            values = yaml.safe_load(f"[{raw}]") if raw.strip() else None
        except yaml.YAMLError:
            values = None
        if not key or not isinstance(values, list) or not values:
            raise _flag_error("grid", text, "PATH=V1,V2,... (e.g. joint_defaults.damping=0.05,0.1)")
        return cls(str(parse_path(key, "--grid ")), tuple(values))


@dataclass(frozen=True)
class Draw:
    """A random value of one field: uniform on [low, high] or normal with a mean and deviation."""

    key: str
    law: Literal["uniform", "normal"]
    a: float
    b: float

    @classmethod
    def parse(cls, text: str, law: Literal["uniform", "normal"]) -> Draw:
        """``PATH=LOW:HIGH`` (uniform) or ``PATH=MEAN:STD`` (normal)."""
        expected = "PATH=LOW:HIGH with LOW <= HIGH" if law == "uniform" else "PATH=MEAN:STD with STD >= 0"
        key, _, raw = text.partition("=")
        try:
            a, b = (float(part) for part in raw.split(":"))
        except ValueError:
            raise _flag_error(law, text, expected) from None
        if not key or not np.isfinite([a, b]).all() or (a > b if law == "uniform" else b < 0):
            raise _flag_error(law, text, expected)
        return cls(str(parse_path(key, f"--{law} ")), law, a, b)

    def sample(self, rng: np.random.Generator) -> float:
        """One value, drawn from ``rng``."""
        value = rng.uniform(self.a, self.b) if self.law == "uniform" else rng.normal(self.a, self.b)
        return float(value)


@dataclass(frozen=True)
class VariantPlan:
    """What to vary and how: everything a worker process needs to build any variant."""

    robot: str
    """A registered robot name."""
    idn: int = 0
    """Instance number of every variant (its names' prefix)."""
    base: str | None = DEFAULT
    """The base, as :func:`~assembler.assemble` takes it."""
    grippers: tuple[tuple[str, str | None], ...] = ()
    """(arm, gripper) choices, as :func:`~assembler.assemble` takes them."""
    fixed: tuple[str, ...] = ()
    """``PATH=VALUE`` overrides given to every variant (``--set``)."""
    grids: tuple[Grid, ...] = ()
    """Fields whose values are combined (cartesian product)."""
    draws: tuple[Draw, ...] = ()
    """Fields drawn at random for each variant."""
    random: int | None = None
    """Random variants per grid point (``--random N``); None when nothing is drawn."""
    seed: int = 0
    """Seed of the draws; with the variant's index, it alone decides the variant's values."""
    spec_paths: tuple[str, ...] = ()
    """User spec files and folders, registered again in worker processes that do not inherit them
    (specs registered from strings in this process are not seen by spawned workers)."""
    cache: bool = True
    """Whether variants may be answered from the compiled-model cache (``--no-cache``: False)."""

    def __post_init__(self) -> None:
        keys = [g.key for g in self.grids] + [d.key for d in self.draws]
        twice = sorted({key for key in keys if keys.count(key) > 1})
        if twice:
            raise AssemblerError(f"{', '.join(twice)}: varied by two flags; vary each field once")
        if self.draws and self.random is None:
            raise AssemblerError("--uniform/--normal draw values for --random N variants; add --random N")
        if self.random is not None and (self.random < 1 or not self.draws):
            raise AssemblerError("--random N needs N >= 1 and at least one --uniform or --normal range")
        if self.seed < 0:
            raise AssemblerError("--seed must be >= 0 and --jobs >= 1")
        if not self.grids and not self.draws:
            raise AssemblerError("nothing to vary: give --grid PATH=V1,V2,... or --random N with ranges")

    @property
    def count(self) -> int:
        """Variants per grid point."""
        return self.random or 1

    def variant_overrides(self) -> list[dict[str, Any]]:
        """The overrides of every variant, in index order: grid points, then draws within each."""
        keys = [grid.key for grid in self.grids]
        variants: list[dict[str, Any]] = []
        for point in itertools.product(*(grid.values for grid in self.grids)):
            for _ in range(self.count):
                rng = np.random.default_rng([self.seed, len(variants)])
                variants.append(
                    {**dict(zip(keys, point, strict=True)), **{d.key: d.sample(rng) for d in self.draws}}
                )
        return variants

    def overrides(self, variant: dict[str, Any]) -> list[Override]:
        """The fixed overrides, then the variant's (named by the flag that chose each value)."""
        flags = {g.key: "--grid " for g in self.grids} | {d.key: f"--{d.law} " for d in self.draws}
        chosen = [Override(parse_path(key), value, flags[key]) for key, value in variant.items()]
        return [*parse_overrides(self.fixed, "--set "), *chosen]

    def check(self) -> None:
        """The fixed overrides are valid and every varied path exists (one error before any work)."""
        cls = with_overrides(robot_class(self.robot), parse_overrides(self.fixed, "--set "))
        check_override_paths(cls, self.overrides(self.variant_overrides()[0]))


@dataclass(frozen=True)
class VariantResult:
    """One variant: its manifest line when written, or its problems."""

    index: int
    overrides: dict[str, Any]
    file: str | None = None
    sha256: str | None = None
    problems: tuple[str, ...] = ()
    seed: int | None = None
    """The seed of the random draws, if any were made."""

    def manifest_line(self) -> str:
        """One JSON line: index, file, sha256 of the file's bytes, every override applied (and the seed)."""
        entry = {"index": self.index, "file": self.file, "sha256": self.sha256, "overrides": self.overrides}
        if self.seed is not None:
            entry["seed"] = self.seed
        return json.dumps(entry, default=str)


def _register_user_specs(spec_paths: Sequence[str]) -> None:
    """Worker start: register the user's specs (a forked worker has them already; this is idempotent)."""
    for path in spec_paths:
        register_specs(path)


def build_variant(plan: VariantPlan, index: int, variant: dict[str, Any], folder: Path) -> VariantResult:
    """Assemble, compile and write variant ``index``; problems are returned, not raised."""
    changes = plan.overrides(variant)
    shown = {c.key: c.value for c in changes}
    seed = plan.seed if plan.draws else None
    try:
        robot = assemble(plan.robot, plan.idn, plan.base, dict(plan.grippers), overrides=changes)
        xml = robot.get_xml(cache=plan.cache)  # compiled first: a variant MuJoCo refuses is never written
    except AssemblerError as error:
        return VariantResult(index, shown, problems=tuple(str(p) for p in error.problems), seed=seed)
    name = f"{plan.robot}_{index:04d}.xml"
    data = xml.encode()
    write_atomically(folder / name, data)
    return VariantResult(index, shown, name, hashlib.sha256(data).hexdigest(), seed=seed)


def _build(job: tuple[VariantPlan, int, dict[str, Any], Path]) -> VariantResult:
    return build_variant(*job)


def write_variants(plan: VariantPlan, folder: str | Path, jobs: int | None = None) -> list[VariantResult]:
    """Build every variant into ``folder`` on ``jobs`` processes (all cores by default) and write
    ``manifest.jsonl`` for the written ones; the results say which failed and why."""
    if jobs is not None and jobs < 1:
        raise AssemblerError("--seed must be >= 0 and --jobs >= 1")
    plan.check()
    target = Path(folder)
    make_folder(target)
    work = [(plan, i, variant, target) for i, variant in enumerate(plan.variant_overrides())]
    workers = min(jobs or os.cpu_count() or 1, len(work))
    if workers <= 1:
        results = [_build(job) for job in work]
    else:
        # Imported here: multiprocessing costs ~50 ms, which every `import assembler` would pay.
        from concurrent.futures import ProcessPoolExecutor

        with ProcessPoolExecutor(
            workers, initializer=_register_user_specs, initargs=(plan.spec_paths,)
        ) as pool:
            results = list(pool.map(_build, work, chunksize=max(1, len(work) // (4 * workers))))
    lines = [r.manifest_line() for r in results if r.file is not None]
    write_atomically(target / MANIFEST, "".join(line + "\n" for line in lines))
    return results


def failures(results: Sequence[VariantResult]) -> list[Problem]:
    """One problem per failed variant's problem, naming the variant and its overrides."""
    problems: list[Problem] = []
    for result in results:
        values = ", ".join(f"{k}={json.dumps(v, default=str)}" for k, v in result.overrides.items())
        problems += [Problem(f"{p}", None, f"variant {result.index} ({values})") for p in result.problems]
    return problems
