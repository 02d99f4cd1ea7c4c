"""A sweep cut into shards for a cluster, and the merge that checks they cover the plan exactly once.

``assembler variants ... --shard I/N`` writes the I-th of N contiguous slices of a plan
(:meth:`~assembler.worlds.variants.plan.VariantPlan.shard`): the same variants, with the same values
and files, as the whole run writes for those indices, since a variant depends on the seed and its
index only. Each shard writes its own manifest and a record (``shard-I-of-N.json``: the plan's
digest, its size, the shard's indices and which of them failed), so a Slurm array's tasks can share
one output folder. ``--merge`` reads the N records and manifests, refuses shards of another plan,
a missing, repeated or overlapping shard and a listed file whose bytes changed, and writes the plan's
``manifest.jsonl`` as the whole run would have.
"""

from __future__ import annotations

import hashlib
import json
import re
from collections.abc import Iterable
from dataclasses import dataclass
from pathlib import Path

from assembler.errors import AssemblerError, Problem
from assembler.files.writing import write_atomically
from assembler.worlds.variants.plan import VariantPlan

MANIFEST = "manifest.jsonl"

_SHARD = re.compile(r"^\s*(\d+)\s*/\s*(\d+)\s*$")


@dataclass(frozen=True)
class Shard:
    """Shard ``number`` of ``shards`` (from 1)."""

    number: int
    shards: int

    @classmethod
    def parse(cls, text: str) -> Shard:
        """``I/N`` with 1 <= I <= N."""
        found = _SHARD.match(text)
        if found is None or not 1 <= int(found[1]) <= int(found[2]):
            raise AssemblerError(f"--shard {text}: expected I/N with 1 <= I <= N, e.g. 3/10")
        return cls(int(found[1]), int(found[2]))

    @property
    def name(self) -> str:
        """``shard-I-of-N``: what the shard's files are called."""
        return f"shard-{self.number}-of-{self.shards}"

    @property
    def manifest_name(self) -> str:
        """The shard's own manifest (the plan's is written by the merge)."""
        return f"manifest-{self.name}.jsonl"

    @property
    def record_name(self) -> str:
        return f"{self.name}.json"

    def write_record(self, folder: Path, plan: VariantPlan, indices: range, failed: Iterable[int]) -> None:
        """What the merge needs to check this shard: the plan it belongs to and what it did."""
        record = {
            "plan": plan.digest(),
            "size": plan.size,
            "shard": [self.number, self.shards],
            "first": indices.start,
            "stop": indices.stop,
            "failed": sorted(failed),
        }
        write_atomically(folder / self.record_name, json.dumps(record) + "\n")


def _record(folder: Path, shard: Shard, plan: VariantPlan) -> tuple[range, list[int]] | Problem:
    """The shard's slice and the variants it reported failed, or why it cannot be merged."""
    path = folder / shard.record_name
    rerun = f"run it: assembler variants ... --shard {shard.number}/{shard.shards}"
    if not path.is_file():
        return Problem(f"{shard.name}: not in {folder}; {rerun}")
    try:
        record = json.loads(path.read_text())
        ours = record["plan"] == plan.digest() and record["size"] == plan.size
        held = range(int(record["first"]), int(record["stop"]))
        failed = [int(index) for index in record["failed"]]
    except (OSError, ValueError, TypeError, KeyError) as error:
        return Problem(f"{path}: not a shard's record ({error}); {rerun}")
    if not ours:
        return Problem(f"{shard.name}: written for another plan (other flags, seed or robot); {rerun}")
    if held != plan.shard(shard.number, shard.shards):
        return Problem(
            f"{shard.name}: holds variants {held.start}..{held.stop - 1}, not its slice of this plan"
        )
    return held, failed


def merge_shards(plan: VariantPlan, folder: str | Path, shards: int) -> int:
    """Check that ``shards`` shards of ``plan`` in ``folder`` cover it exactly once, with every listed
    file's bytes as their manifests say, and write the plan's manifest; returns how many variants it
    lists. Every problem is one line; nothing is written unless all shards are there and complete."""
    target = Path(folder)
    problems: list[Problem] = []
    lines: list[tuple[int, str]] = []
    for number in range(1, shards + 1):
        shard = Shard(number, shards)
        found = _record(target, shard, plan)
        if isinstance(found, Problem):
            problems.append(found)
            continue
        held, failed = found
        named: set[int] = set()
        listed = _checked_lines(target, shard, held, problems, named)
        done = named | set(failed)
        unwritten = [index for index in held if index not in done]
        if unwritten:
            first = unwritten[0]
            problems.append(
                Problem(f"{shard.name}: {len(unwritten)} variants not written from {first} on; run it again")
            )
        problems += [
            Problem(f"variant {index}: failed in {shard.name}; see its report, run it again")
            for index in failed
        ]
        lines += listed
    if problems:
        raise AssemblerError(problems)
    write_atomically(target / MANIFEST, "".join(line + "\n" for _, line in sorted(lines)))
    return len(lines)


def _checked_lines(
    target: Path, shard: Shard, indices: range, problems: list[Problem], named: set[int]
) -> list[tuple[int, str]]:
    """The shard's manifest lines whose file has the bytes the shard wrote; every index the manifest
    names is added to ``named``, checked or not."""
    path = target / shard.manifest_name
    try:
        text = path.read_text()
    except OSError as error:
        problems.append(Problem(f"{shard.name}: {path.name} cannot be read ({error.strerror}); run it again"))
        return []
    found: list[tuple[int, str]] = []
    for line in text.splitlines():
        entry = json.loads(line)
        index, name = int(entry["index"]), str(entry["file"])
        named.add(index)
        try:
            digest = hashlib.sha256((target / name).read_bytes()).hexdigest()
        except OSError:
            digest = None
        if index not in indices:
            problems.append(Problem(f"{shard.name}: lists variant {index}, outside its slice"))
        elif digest != entry["sha256"]:
            problems.append(Problem(f"{name}: missing or changed since {shard.name} wrote it; run it again"))
        else:
            found.append((index, line))
    return found
