"""Building the variants of a plan into a folder, in parallel, with a manifest that never lies.

Every variant is a model MuJoCo accepts before its file is written (atomically): either compiled,
or (most sweeps) written as an edit of the robot's XML, compiled once per process
(:mod:`~assembler.patch.variant_files` says how that keeps the guarantee); ``manifest.jsonl`` lists the
written ones (index, file, sha256, overrides). The folder's previous manifest is removed before
anything is written and the new one is written once, at the end or when the run is interrupted,
listing only files this run wrote whole: at no moment does a manifest name a file that is not
there with its digest. A variant that fails is reported with its overrides while the others are
still written: one sample outside a field's range should not cost the other 999 models, and the
exit code still says the sweep is incomplete. Workers exit when the process that started them
dies, so a killed run leaves no orphans.
"""

from __future__ import annotations

import contextlib
import hashlib
import itertools
import json
import os
import signal
import threading
import time
from collections.abc import Callable, Iterable, Iterator, Sequence
from concurrent.futures import ProcessPoolExecutor
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import mujoco

from assembler.errors import AssemblerError, Problem
from assembler.files.writing import cannot_write, make_folder, write_atomically
from assembler.patch.variant_files import TEXT_SECTIONS, PatchedXml
from assembler.registry.catalog import register_specs
from assembler.registry.instances import assemble
from assembler.registry.lookup import robot_class
from assembler.spec.documents import parse_overrides
from assembler.worlds.variants.plan import VariantPlan
from assembler.worlds.variants.shards import MANIFEST, Shard

ORPHAN_CHECK_SECONDS = 0.5
"""How often a worker looks whether the process that started it is still there."""

FROM_FILES_AT = 4
"""Variants per worker from which meshes are read from their files rather than the mesh store:
MuJoCo's own asset cache keeps meshes read from files processed (hulls, normals, inertia) for the
process's next compiles, and not those given in memory, so after the first decode each later
variant compiles in a fraction of the time (Panda: 0.16 s against 0.33 s for compile and XML)."""


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


@dataclass
class VariantRun:
    """What a run wrote, which variants failed, and how many different models came out."""

    results: list[VariantResult]
    no_effect: list[str] = field(default_factory=list)
    """Varied fields that changed nothing in the compiled model (:mod:`assembler.worlds.variants.effects`)."""

    @property
    def written(self) -> list[VariantResult]:
        """The variants whose file was written."""
        return [result for result in self.results if result.file is not None]

    @property
    def distinct(self) -> int:
        """How many different models the written variants are (by their files' digests)."""
        return len({result.sha256 for result in self.written})


@dataclass
class WrittenCounts:
    """How this process's variants were made, for tests and the benchmark."""

    edited: int = 0
    """Written as the robot's XML with the variant's values (no compile of their own)."""

    compiled: int = 0
    """Built and compiled in full (a structural change, ``bodies:`` scales, ``--cache``)."""


counts = WrittenCounts()


@dataclass
class _Patcher:
    """This process's :class:`PatchedXml` of the robot being varied (one at a time): made once for
    every plan that varies the same robot with the same ``--set`` overrides."""

    robot: tuple[Any, ...] | None = None
    patched: PatchedXml | None = None

    def of(self, plan: VariantPlan, meshes: bool) -> PatchedXml | None:
        """The plan's robot compiled once, or None when its variants are compiled (``--cache`` keeps
        each variant's compiled model, so those are compiled)."""
        if plan.store:
            return None
        meshes = plan.cache and meshes
        robot = self._robot(plan, meshes)
        if self.robot != robot:
            self.robot, self.patched = robot, None
            fixed = parse_overrides(plan.fixed, "--set ")
            with contextlib.suppress(AssemblerError):  # the robot alone fails: each variant says why
                self.patched = PatchedXml.of(
                    plan.robot, plan.idn, plan.base, dict(plan.grippers), fixed, plan.cache, meshes
                )
        return self.patched

    def for_models(self, plan: VariantPlan) -> PatchedXml | None:
        """As :meth:`of`, for variants' models: the one held serves whatever its meshes' source (that
        changes the text alone)."""
        if self.robot is not None and self.robot[:-1] == self._robot(plan, True)[:-1] and not plan.store:
            return self.patched
        return self.of(plan, meshes=True)

    @staticmethod
    def _robot(plan: VariantPlan, meshes: bool) -> tuple[Any, ...]:
        cls = robot_class(plan.robot)  # the class registered now: a spec registered again is another
        return (cls, plan.idn, plan.base, plan.grippers, plan.fixed, meshes)


_patcher = _Patcher()


def edited_by_text(plan: VariantPlan) -> bool:
    """True when every field ``plan`` varies is one the robot's XML is edited for (no variant of
    its own compiled), unless a value turns out structural (see :mod:`.patched`)."""
    return not plan.store and all(key.split(".")[0].split("[")[0] in TEXT_SECTIONS for key in plan.varied())


def variant_xml(plan: VariantPlan, variant: dict[str, Any], meshes: bool = True) -> str:
    """The emitted MJCF of one variant (nothing written): the robot's XML with the variant's values
    when a patch describes the variant, else compiled and emitted; ``meshes`` False reads meshes
    from their files (see :data:`FROM_FILES_AT`)."""
    patched = _patcher.of(plan, meshes)
    xml = patched.xml(plan.overrides(variant)) if patched is not None else None
    if xml is not None:
        counts.edited += 1
        return xml
    counts.compiled += 1
    robot = assemble(plan.robot, plan.idn, plan.base, dict(plan.grippers), overrides=plan.overrides(variant))
    return robot.get_xml(cache=plan.cache, store=plan.store, meshes=meshes)


def variant_model(plan: VariantPlan, variant: dict[str, Any]) -> mujoco.MjModel | None:
    """The model of one variant patched in memory from the plan's robot (what its written text loads
    to), or None when the variant is compiled (:func:`variant_xml`) and its text must be loaded."""
    patched = _patcher.for_models(plan)
    return patched.compiled(plan.overrides(variant)) if patched is not None else None


def variants_surely_differ(plan: VariantPlan, first: dict[str, Any], second: dict[str, Any]) -> bool:
    """True when two variants are different models, told from their patches alone (see
    :meth:`~assembler.patch.variant_files.PatchedXml.surely_differ`); False: not told that way."""
    patched = _patcher.for_models(plan)
    return patched is not None and patched.surely_differ(plan.overrides(first), plan.overrides(second))


def build_variant(
    plan: VariantPlan, index: int, variant: dict[str, Any], folder: Path, meshes: bool = True
) -> VariantResult:
    """Assemble, compile and write variant ``index``; problems are returned, not raised."""
    shown = {change.key: change.value for change in plan.overrides(variant)}
    seed = plan.seed if plan.draws else None
    try:
        xml = variant_xml(plan, variant, meshes)  # compiled first: a variant MuJoCo refuses is never written
    except AssemblerError as error:
        return VariantResult(index, shown, problems=tuple(str(p) for p in error.problems), seed=seed)
    name = f"{plan.robot}_{index:04d}.xml"
    data = xml.encode()
    write_atomically(folder / name, data)
    return VariantResult(index, shown, name, hashlib.sha256(data).hexdigest(), seed=seed)


Job = tuple[VariantPlan, int, dict[str, Any], Path, bool]


def _build(job: Job) -> VariantResult:
    return build_variant(*job)


def _exit_with_parent(parent: int) -> None:
    while os.getppid() == parent:
        time.sleep(ORPHAN_CHECK_SECONDS)
    os._exit(1)  # the run that wanted this work is gone


def _start_worker(spec_paths: Sequence[str], parent: int) -> None:
    """Worker start: follow the parent, leave Ctrl-C to it (the terminal sends it to every process
    of the run; the parent says ``interrupted`` once, no worker prints a traceback), and register
    the user's specs (idempotent when forked)."""
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    threading.Thread(target=_exit_with_parent, args=(parent,), daemon=True, name="orphan-guard").start()
    for path in spec_paths:
        register_specs(path)


BLOCK = 4096
"""Variants handed to the workers at a time: a huge plan is never enumerated whole, only this many
variants' overrides exist at once (besides the results)."""


def _results(plan: VariantPlan, work: Iterable[Job], count: int, workers: int) -> Iterator[VariantResult]:
    if workers <= 1:
        yield from map(_build, work)
        return
    pool = ProcessPoolExecutor(workers, initializer=_start_worker, initargs=(plan.spec_paths, os.getpid()))
    chunksize = max(1, min(count, BLOCK) // (4 * workers))
    try:
        for block in itertools.batched(work, BLOCK) if hasattr(itertools, "batched") else _batched(work):
            yield from pool.map(_build, block, chunksize=chunksize)
    finally:  # interrupted: what has not started is dropped; what runs finishes its file whole
        pool.shutdown(wait=True, cancel_futures=True)


def _batched(work: Iterable[Job]) -> Iterator[tuple[Job, ...]]:
    """``itertools.batched`` (Python 3.12) for 3.10 and 3.11."""
    iterator = iter(work)
    while block := tuple(itertools.islice(iterator, BLOCK)):
        yield block


def write_manifest(folder: Path, results: Sequence[VariantResult], name: str = MANIFEST) -> None:
    """The manifest of the written variants, in index order, written atomically."""
    lines = [
        result.manifest_line() for result in sorted(results, key=lambda r: r.index) if result.file is not None
    ]
    write_atomically(folder / name, "".join(line + "\n" for line in lines))


Progress = Callable[[int, int], None]
"""Told ``(done, count)`` as a run goes on: variants finished so far (written or failed) of the run's."""


def run_variants(
    plan: VariantPlan,
    folder: str | Path,
    shard: Shard | None = None,
    progress: Progress | None = None,
) -> list[VariantResult]:
    """Build every variant of ``plan`` (or of one ``shard`` of it) into ``folder``; the manifest lists
    what was written, even when interrupted. A shard writes its own manifest and record
    (:mod:`.shards`), so shards of one plan can share a folder; ``merge_shards`` makes the plan's."""
    plan.check()
    target = Path(folder)
    make_folder(target)
    manifest = MANIFEST if shard is None else shard.manifest_name
    with cannot_write(target / manifest):
        (target / manifest).unlink(missing_ok=True)  # the earlier run's: its files are about to change
    indices = range(plan.size) if shard is None else plan.shard(shard.number, shard.shards)
    workers = max(1, min(plan.jobs or os.cpu_count() or 1, len(indices)))
    if plan.jobs is None and edited_by_text(plan):
        workers = 1  # each variant costs milliseconds; a worker's own compile of the robot costs more
    from_store = len(indices) < FROM_FILES_AT * workers
    work = ((plan, index, plan.variant(index), target, from_store) for index in indices)
    results: list[VariantResult] = []
    try:
        for result in _results(plan, work, len(indices), workers):
            results.append(result)
            if progress is not None:
                progress(len(results), len(indices))
    finally:
        write_manifest(target, results, manifest)
        if shard is not None:
            shard.write_record(target, plan, indices, [r.index for r in results if r.file is None])
    return results


def failures(results: Sequence[VariantResult]) -> list[Problem]:
    """One problem per failed variant's problem, naming the variant and its overrides."""
    problems: list[Problem] = []
    for result in results:
        values = ", ".join(f"{k}={json.dumps(v, default=str)}" for k, v in result.overrides.items())
        problems += [Problem(f"{p}", None, f"variant {result.index} ({values})") for p in result.problems]
    return problems
