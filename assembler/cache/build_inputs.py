"""What defines an assembly, as plain frozen data: the compile service keys the cache on it.

A robot model hands these out (``RobotModel.build_inputs()``) without reading any MJCF: each
part's validated spec, its class, its idn, the MJCF file its spec names, the joint values set
through the API, and the robot's placement. The MJCF's content is not here: the cache entry
lists every file the compile read and a lookup checks them.
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class JointEdit:
    """One ``set_joint_attribute`` call."""

    attribute: str
    values: tuple[float, ...]
    force: bool


@dataclass(frozen=True)
class PartInputs:
    """Everything one part contributes to an assembly."""

    family: str
    """robot, base or gripper."""

    classes: tuple[str, ...]
    """``module.qualname`` of the part's class, each of its bases and its adaptation, if any (see
    ``PartModel.adaptation``): the code that builds it."""

    spec_json: str
    """The validated spec (``extends`` merged, overrides applied) as canonical JSON."""

    mjcf: str
    """The model file the spec names (its ``mjcf``, or its ``urdf``), resolved in this environment (a
    ``package://`` path differs between environments)."""

    idn: str
    """The instance's idn, as ``repr`` writes it (``0`` and ``'0'`` differ)."""

    joint_edits: tuple[JointEdit, ...] = ()
    """``set_joint_attribute`` calls on this part, in order."""

    spec_made: bool = True
    """False for a part whose class (or a base class) is hand-written Python: the cache cannot see
    what its code does, so such an assembly is always compiled."""


@dataclass(frozen=True)
class BuildInputs:
    """A robot with its base and grippers, and where it stands."""

    robot: PartInputs
    base: PartInputs | None
    grippers: tuple[tuple[str, PartInputs], ...]
    """(arm, gripper) pairs, right first."""

    root_pos: tuple[float, ...] | None = None
    """``set_base_xpos``'s result: the robot root's position, or None for the MJCF's own."""

    root_quat: tuple[float, ...] | None = None
    """``set_base_ori``'s result: the robot root's orientation, or None for the MJCF's own."""

    @property
    def parts(self) -> tuple[PartInputs, ...]:
        """Every part: robot, base, grippers."""
        base = (self.base,) if self.base is not None else ()
        return (self.robot, *base, *(gripper for _, gripper in self.grippers))

    @property
    def cacheable(self) -> bool:
        """True when every part is made from a spec."""
        return all(part.spec_made for part in self.parts)
