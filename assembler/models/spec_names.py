"""Names a part's spec gives that must exist in its MJCF: bodies, joints (names or globs), sites,
geoms, sensors, actuators. Each miss is one problem at the spec field, with the closest name that exists.

The checks read the parsed MJCF (no compile), so ``assembler validate`` reports them all at once.
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import mujoco

from assembler.errors import Problem, did_you_mean, summarize_names
from assembler.models.joint_rules import SpecProblem, matching_joints, no_match
from assembler.spec.fieldpath import FieldPath


class NameCheck:
    """Collects the problems of one part's names against its MJCF."""

    def __init__(self, problem: SpecProblem, mjspec: mujoco.MjSpec, joint_names: Sequence[str]) -> None:
        self.problem = problem
        self.mjspec = mjspec
        self.joint_names = list(joint_names)
        self.problems: list[Problem] = []

    def _element(self, path: FieldPath, name: str, what: str, names: Iterable[str]) -> None:
        known = sorted(n for n in names if n)
        if name not in known:
            plural = "Bodies" if what == "body" else f"{what.capitalize()}s"
            suggestion = did_you_mean(name, known)
            message = f"no {what} named '{name}' in the MJCF.{suggestion} {plural}: {summarize_names(known)}"
            self.problems.append(self.problem(path, message))

    def body(self, path: FieldPath, name: str) -> None:
        """``name`` must be a body of the MJCF."""
        self._element(path, name, "body", (b.name for b in self.mjspec.bodies[1:]))  # not the world

    def site(self, path: FieldPath, name: str) -> None:
        """``name`` must be a site of the MJCF."""
        self._element(path, name, "site", (s.name for s in self.mjspec.sites))

    def geom(self, path: FieldPath, name: str) -> None:
        """``name`` must be a geom of the MJCF."""
        self._element(path, name, "geom", (g.name for g in self.mjspec.geoms))

    def sensor(self, path: FieldPath, name: str) -> None:
        """``name`` must be a sensor of the MJCF."""
        self._element(path, name, "sensor", (s.name for s in self.mjspec.sensors))

    def actuator(self, path: FieldPath, name: str) -> None:
        """``name`` must be an actuator of the MJCF."""
        self._element(path, name, "actuator", (a.name for a in self.mjspec.actuators))

    def joint_patterns(self, path: FieldPath, patterns: Sequence[str]) -> None:
        """Each name or glob in ``patterns`` (a list at ``path``) must match a joint."""
        for index, pattern in enumerate(patterns):
            if not matching_joints(pattern, self.joint_names):
                self.problems.append(self.problem(path.child(index), no_match(pattern, self.joint_names)))
