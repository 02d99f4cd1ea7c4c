"""The errors a user can cause, each printed as one readable line per problem.

Every error the assembler raises on purpose derives from :class:`AssemblerError` (a ``ValueError``),
so the CLI catches exactly these and prints them without a traceback; anything else is a bug and
is allowed to crash loudly.
"""

from __future__ import annotations

import difflib
from collections.abc import Iterable, Sequence
from dataclasses import dataclass

from assembler.spec.fieldpath import FieldPath


@dataclass(frozen=True)
class Location:
    """Where a problem sits in a user's file (1-based line and column, as editors count)."""

    file: str
    line: int | None = None
    column: int | None = None

    def __str__(self) -> str:
        if self.line is None:
            return self.file
        if self.column is None:
            return f"{self.file}:{self.line}"
        return f"{self.file}:{self.line}:{self.column}"


@dataclass(frozen=True)
class Problem:
    """One thing wrong with the user's input: where, which field, what, and what to do."""

    message: str
    location: Location | None = None
    path: FieldPath | str | None = None
    """The field the problem is about (a spec field path), or a label such as ``--set init_qpos[7]``."""

    def __str__(self) -> str:
        parts = [str(self.location)] if self.location else []
        if self.path:
            parts.append(str(self.path))
        parts.append(self.message)
        return ": ".join(parts)


class AssemblerError(ValueError):
    """A problem the user can fix. ``str(error)`` is one line per problem."""

    def __init__(self, problems: Problem | str | Sequence[Problem]) -> None:
        if isinstance(problems, (str, Problem)):
            problems = [problems if isinstance(problems, Problem) else Problem(problems)]
        self.problems: list[Problem] = list(problems)
        super().__init__("\n".join(str(p) for p in self.problems))


class SpecError(AssemblerError):
    """A spec file (YAML) is malformed, invalid, or inconsistent with its MJCF."""


class MjcfError(AssemblerError):
    """An MJCF file or asset cannot be read, or MuJoCo refuses to compile the assembly."""


class MissingPackageError(MjcfError):
    """A spec points into a package (``package://``) that is not installed."""

    def __init__(self, problems: Problem | str | Sequence[Problem], package: str = "") -> None:
        super().__init__(problems)
        self.package = package
        """The package's name (``robosuite``, ``example-robot-data``), for "not installed" notes;
        empty when the code that raised it did not say."""


class RegistryError(AssemblerError):
    """A name is unknown to a registry, or two definitions claim the same name."""


class MujocoWarning(UserWarning):
    """A warning MuJoCo gave while the assembler read or compiled a model."""


class AssemblerWarning(UserWarning):
    """Something the user wrote that a consumer of the model (e.g. robosuite) will not do as written."""


class JointAttributeError(AssemblerError):
    """``set_joint_attribute`` got an unsupported attribute or the wrong number of values."""


def closest_match(name: str, candidates: Iterable[str]) -> str | None:
    """The candidate most similar to ``name``, if any is similar enough to suggest."""
    matches = difflib.get_close_matches(name, list(candidates), n=1, cutoff=0.6)
    return matches[0] if matches else None


def did_you_mean(name: str, candidates: Iterable[str]) -> str:
    """`` Did you mean 'X'?`` when a close match exists, else the empty string."""
    match = closest_match(name, candidates)
    return f" Did you mean '{match}'?" if match else ""


def summarize_names(names: Sequence[str], limit: int = 12) -> str:
    """A short, readable list of names: all of them, or a head and tail when there are many."""
    if not names:
        return "(none)"
    if len(names) <= limit:
        return ", ".join(names)
    head = ", ".join(names[: limit - 2])
    return f"{head}, ... ({len(names) - limit + 1} more), {names[-1]}"
