"""RA501-RA503: the sites, geoms and bodies that controllers and tasks look up by name.

robosuite's tasks find a gripper's grip site, its finger pads (for grasp checks) and the arm's
end-effector body by name. A missing name fails only when a task runs, far from the spec; a pad
that cannot collide makes every grasp check false without any error.
"""

from __future__ import annotations

from collections.abc import Iterator

import mujoco

from assembler.checks.finding import Finding
from assembler.checks.target import LintTarget
from assembler.models import GripperModel, ManipulatorModel, PartModel
from assembler.spec.fieldpath import FieldPath
from assembler.tools.lint.geometry import collides

FINGERPAD_ROLES: tuple[str, ...] = ("left_fingerpad", "right_fingerpad")
"""The important_geoms roles robosuite's grasp check (``_check_grasp``) reads."""

_OBJECTS = {
    "important_sites": mujoco.mjtObj.mjOBJ_SITE,
    "important_geoms": mujoco.mjtObj.mjOBJ_GEOM,
    "important_sensors": mujoco.mjtObj.mjOBJ_SENSOR,
    "eef_body": mujoco.mjtObj.mjOBJ_BODY,
    "eef_bodies": mujoco.mjtObj.mjOBJ_BODY,
}


def _declared_names(target: LintTarget) -> Iterator[tuple[PartModel, FieldPath, str]]:
    """(part, spec path, prefixed name) of every name a robot or gripper spec declares."""
    for part in target.parts:
        if isinstance(part, ManipulatorModel):
            for arm, body in part.eef_name.items():
                yield part, FieldPath(("eef_bodies", arm)), body
        if isinstance(part, GripperModel):
            yield part, FieldPath(("eef_body",)), part.eef_body
            for role, site in part.important_sites.items():
                yield part, FieldPath(("important_sites", role)), site
            for role, geoms in part.important_geoms.items():
                for index, geom in enumerate(geoms):
                    yield part, FieldPath(("important_geoms", role, index)), geom
            for role, sensor in part.important_sensors.items():
                yield part, FieldPath(("important_sensors", role)), sensor


def missing_important_names(target: LintTarget) -> Iterator[Finding]:
    """RA501 (error): an end-effector body or a gripper's important site, geom or sensor is missing."""
    for part, path, name in _declared_names(target):
        kind = _OBJECTS[str(path[0])]
        if mujoco.mj_name2id(target.model, kind, name) >= 0:
            continue
        what = kind.name.removeprefix("mjOBJ_").lower()
        yield Finding(
            code="RA501",
            severity="error",
            subject=name,
            why=f"{path} names {what} {name}, which the assembled model does not have",
            fix=f"name an existing {what} in the spec, or add it to the MJCF",
            location=target.spec_location(part, path),
        )


def missing_fingerpads(target: LintTarget) -> Iterator[Finding]:
    """RA502 (warning): a gripper with moving fingers declares no left_fingerpad / right_fingerpad geoms."""
    for part in target.parts:
        if not isinstance(part, GripperModel) or part.dof_joints == 0:
            continue
        missing = [role for role in FINGERPAD_ROLES if not part.spec.important_geoms.get(role)]
        if not missing:
            continue
        yield Finding(
            code="RA502",
            severity="warning",
            subject=type(part).__name__,
            why=f"important_geoms has no {' or '.join(missing)}: robosuite's grasp check has no pads to test",
            fix="list the finger pads' collision geoms as important_geoms left_fingerpad and right_fingerpad",
            location=target.spec_location(part, FieldPath(("important_geoms",))),
        )


def important_geoms_without_contact(target: LintTarget) -> Iterator[Finding]:
    """RA503 (warning): an important geom has contype and conaffinity 0, so it never touches anything."""
    for part in target.parts:
        if not isinstance(part, GripperModel):
            continue
        for role, geoms in part.important_geoms.items():
            for geom in geoms:
                index = mujoco.mj_name2id(target.model, mujoco.mjtObj.mjOBJ_GEOM, geom)
                if index < 0 or collides(target.model, index):
                    continue
                yield Finding(
                    code="RA503",
                    severity="warning",
                    subject=geom,
                    why=f"important_geoms.{role} names a geom that never collides (contype, conaffinity 0)",
                    fix="name the collision geom instead (group 0), or give this one a contype/conaffinity",
                    location=target.spec_location(part, FieldPath(("important_geoms", role))),
                )
