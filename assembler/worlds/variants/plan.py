"""What to vary and how: grid values and seeded random draws of spec fields, checked before any work.

Variant ``i`` is the robot with its grid point's values and, for ``--random N``, values drawn
from ``numpy.random.default_rng([seed, i])``: they depend on the seed and the index only, so a
run is reproducible whatever the number of worker processes.
"""

from __future__ import annotations

import hashlib
import json
import math
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass
from typing import Any, Literal

import numpy as np
import yaml
from numpy.typing import NDArray

from assembler.errors import AssemblerError
from assembler.registry.catalog import check_override_paths, with_overrides
from assembler.registry.lookup import robot_class
from assembler.spec.documents import Override, parse_overrides, parse_path
from assembler.spec.part_arguments import DEFAULT


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
    store: bool = False
    """Whether each variant's compiled model is kept in the cache (``--cache``): a sweep's models
    are rarely asked for again, and each can be tens of megabytes."""
    jobs: int | None = None
    """Worker processes (None: one per core, or this process alone when every varied field is written
    as an edit of the robot's XML, where a worker's own compile of the robot costs more than it saves)."""

    def __post_init__(self) -> None:
        keys = [g.key for g in self.grids] + [d.key for d in self.draws]
        twice = sorted({key for key in keys if keys.count(key) > 1})
        if twice:
            raise AssemblerError(f"{', '.join(twice)}: varied by two flags; vary each field once")
        if self.draws and self.random is None:
            raise AssemblerError("--uniform/--normal draw values for --random N variants; add --random N")
        if self.random is not None and (self.random < 1 or not self.draws):
            raise AssemblerError("--random N needs N >= 1 and at least one --uniform or --normal range")
        if self.seed < 0 or (self.jobs is not None and self.jobs < 1):
            raise AssemblerError("--seed must be >= 0 and --jobs >= 1")
        if not self.grids and not self.draws:
            raise AssemblerError("nothing to vary: give --grid PATH=V1,V2,... or --random N with ranges")

    @property
    def count(self) -> int:
        """Variants per grid point."""
        return self.random or 1

    @property
    def size(self) -> int:
        """How many variants the plan describes: every grid point times the draws at each."""
        return math.prod(len(grid.values) for grid in self.grids) * self.count

    def variant(self, index: int) -> dict[str, Any]:
        """The overrides of variant ``index``: its grid point (the last grid varying fastest, as
        ``itertools.product``) and, for draws, values from ``default_rng([seed, index])``. Each variant
        is computed alone, so a shard or a huge plan never enumerates the others."""
        if not 0 <= index < self.size:
            raise IndexError(f"variant {index} of a plan of {self.size}")
        point = index // self.count
        values: dict[str, Any] = {}
        for grid in reversed(self.grids):
            point, position = divmod(point, len(grid.values))
            values[grid.key] = grid.values[position]
        chosen = {grid.key: values[grid.key] for grid in self.grids}
        if self.draws:
            rng = np.random.default_rng([self.seed, index])
            chosen |= {draw.key: draw.sample(rng) for draw in self.draws}
        return chosen

    def positions(self, indices: Sequence[int]) -> dict[str, NDArray[np.int64]]:
        """Each grid's position in its values (``grid.values[position]``) at ``indices``."""
        positions: dict[str, NDArray[np.int64]] = {}
        point = np.asarray(indices, dtype=np.int64) // self.count
        for grid in reversed(self.grids):
            point, positions[grid.key] = np.divmod(point, len(grid.values))
        return positions

    def columns(
        self, indices: Sequence[int]
    ) -> tuple[dict[str, NDArray[np.int64]], dict[str, NDArray[np.float64]]]:
        """The values of :meth:`variant` at ``indices``, field by field: each grid's position
        (:meth:`positions`) and each draw's value, one array entry per index."""
        drawn = np.empty((len(self.draws), len(indices)))
        for column, index in enumerate(indices):  # one generator per variant, as variant() draws
            rng = np.random.default_rng([self.seed, index])
            drawn[:, column] = [draw.sample(rng) for draw in self.draws]
        return self.positions(indices), {draw.key: drawn[row] for row, draw in enumerate(self.draws)}

    def variants(self, indices: Iterable[int] | None = None) -> Iterator[dict[str, Any]]:
        """The overrides of the variants at ``indices`` (default: all, in index order), one at a time."""
        for index in range(self.size) if indices is None else indices:
            yield self.variant(index)

    def variant_overrides(self) -> list[dict[str, Any]]:
        """The overrides of every variant, in index order: grid points, then draws within each."""
        return list(self.variants())

    def shard(self, number: int, shards: int) -> range:
        """The indices of shard ``number`` of ``shards`` (from 1): the plan cut into contiguous slices
        whose sizes differ by one at most, disjoint, covering it exactly once."""
        if not 1 <= number <= shards:
            raise AssemblerError(f"--shard {number}/{shards}: expected I/N with 1 <= I <= N, e.g. 3/10")
        return range((number - 1) * self.size // shards, number * self.size // shards)

    def digest(self) -> str:
        """What decides the variants' values and files (robot, parts, fixed and varied fields, seed),
        hashed: shards of one plan carry the same digest, so a merge can tell them from another's."""
        decided = {
            "robot": self.robot,
            "idn": self.idn,
            "base": self.base,
            "grippers": self.grippers,
            "fixed": self.fixed,
            "grids": [(grid.key, list(grid.values)) for grid in self.grids],
            "draws": [(draw.key, draw.law, draw.a, draw.b) for draw in self.draws],
            "random": self.random,
            "seed": self.seed,
        }
        return hashlib.sha256(json.dumps(decided, sort_keys=True, default=str).encode()).hexdigest()[:16]

    def flag_of(self, key: str) -> str:
        """The flag that varies ``key``: ``--grid``, ``--uniform`` or ``--normal``."""
        laws = {draw.key: f"--{draw.law}" for draw in self.draws}
        return laws.get(key, "--grid")

    def varied(self) -> list[str]:
        """The fields the plan varies, grids first."""
        return [grid.key for grid in self.grids] + [draw.key for draw in self.draws]

    def overrides(self, variant: dict[str, Any]) -> list[Override]:
        """The fixed overrides, then the variant's (named by the flag that chose each value)."""
        flags = {g.key: "--grid " for g in self.grids} | {d.key: f"--{d.law} " for d in self.draws}
        chosen = [Override(parse_path(key), value, flags[key]) for key, value in variant.items()]
        return [*parse_overrides(self.fixed, "--set "), *chosen]

    def check(self) -> None:
        """The fixed overrides are valid and every varied path exists (one error before any work)."""
        cls = with_overrides(robot_class(self.robot), parse_overrides(self.fixed, "--set "))
        check_override_paths(cls, self.overrides(self.variant(0)))
