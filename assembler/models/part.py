"""PartModel: what robots, bases and grippers share — a spec, its MJCF, joint values, a name prefix.

Each instance loads a private copy of its MJCF, removes what the spec removes (actuation of named
joints, the free joint), resolves its joint parameters (file, rules, overrides) with their sources,
and hands out fresh copies of the prepared spec to attach into an assembly. Element lists are
read from the prepared spec, so they stay consistent after removals.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, ClassVar

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import Location, MjcfError, Problem, SpecError, summarize_names
from assembler.mjcf import compose
from assembler.mjcf.added_joints import add_joints
from assembler.mjcf.keyframe import compile_with_home
from assembler.mjcf.removal import remove_free_joints, remove_joints
from assembler.mjcf.source import MjcfSource, load_mjcf
from assembler.mjcf.structure import root_body_name
from assembler.models.joint_rules import (
    JointTable,
    JointValue,
    apply_default_rules,
    apply_overrides,
    matching_joints,
)
from assembler.models.kept_elements import require_kept_alone
from assembler.registry import RegisteringMeta
from assembler.schema import JOINT_RULE_ATTRIBUTES, PartSpec
from assembler.yaml_source import DataPath

if TYPE_CHECKING:
    from assembler.loader import LoadedSpec

FloatArray = NDArray[np.float64]

SETTABLE_JOINT_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")
"""Attributes ``set_joint_attribute`` accepts: the ones whose MJCF origin the assembler tracks."""

COLLISION_GROUP = 0
VISUAL_GROUP = 1
FREE = mujoco.mjtJoint.mjJNT_FREE


def joint_attribute(joint: mujoco.MjsJoint, attribute: str) -> float:
    """A joint's scalar value of ``attribute`` (damping/stiffness: the linear coefficient)."""
    value = getattr(joint, attribute)
    return float(value[0]) if hasattr(value, "__len__") else float(value)


def set_joint_attribute_value(joint: mujoco.MjsJoint, attribute: str, value: float) -> None:
    """Set a scalar joint attribute (damping and stiffness are polynomial arrays since MuJoCo 3.7)."""
    if attribute in ("damping", "stiffness"):
        coefficients = np.array(getattr(joint, attribute), dtype=float)
        coefficients[0] = value
        setattr(joint, attribute, coefficients)
    else:
        setattr(joint, attribute, value)


class PartModel(metaclass=RegisteringMeta):
    """A robot, base or gripper built from its spec."""

    abstract = True
    family: ClassVar[str] = "part"

    spec: ClassVar[PartSpec]
    """The validated spec this class was made from."""

    loaded: ClassVar[LoadedSpec | None] = None
    """The spec's file and positions, for pointing errors at the line that caused them."""

    collision_rgba: ClassVar[tuple[float, float, float, float]] = (0.0, 0.5, 0.0, 1.0)

    def __init__(self, idn: int | str = 0) -> None:
        self.idn = idn
        self.source: MjcfSource = self._load_source()
        self._root_name = root_body_name(self.source)
        self.prepared: mujoco.MjSpec = self._prepare()
        self._joint_names = [j.name for j in self.prepared.joints if j.type != FREE]
        self.joint_values: JointTable = self._resolve_joint_values()
        self._check_init_qpos()

    # ----- construction -------------------------------------------------------------------

    def locate(self, path: DataPath) -> Location:
        """The spec position of a field, for error messages."""
        if self.loaded is not None:
            return self.loaded.location(path)
        return Location(f"<class {type(self).__qualname__}>")

    def spec_problem(self, path: DataPath, message: str) -> Problem:
        """A problem located at a field of this part's spec."""
        return Problem(message, self.locate(path), ".".join(str(p) for p in path))

    def _load_source(self) -> MjcfSource:
        try:
            return load_mjcf(self.spec.mjcf, self.spec.mjcf_fixes)
        except MjcfError as error:
            where = self.locate(("mjcf",))
            located = [Problem(p.message, where, "mjcf") for p in error.problems]
            raise type(error)(located) from None

    def _removed_joints(self) -> list[str]:
        patterns: list[str] = list(getattr(self.spec, "remove_actuation", []))
        names = self.source.joint_names
        removed: list[str] = []
        problems = []
        for index, pattern in enumerate(patterns):
            matched = matching_joints(pattern, names)
            if not matched:
                problems.append(
                    self.spec_problem(
                        ("remove_actuation", index),
                        f"no joint matches '{pattern}'. Joints: {summarize_names(names)}",
                    )
                )
            removed += [name for name in matched if name not in removed]
        if problems:
            raise SpecError(problems)
        return removed

    def _prepare(self) -> mujoco.MjSpec:
        spec = self.source.new_spec()
        for key in list(spec.keys):  # the assembler writes one merged "home" keyframe instead
            spec.delete(key)
        remove_joints(spec, self._removed_joints())
        if getattr(self.spec, "remove_free_joint", False):
            remove_free_joints(spec)
        try:
            add_joints(spec, getattr(self.spec, "added_joints", []))
        except MjcfError as error:
            raise MjcfError(
                [self.spec_problem(("added_joints",), p.message) for p in error.problems]
            ) from None
        return spec

    def _resolve_joint_values(self) -> JointTable:
        # Rules index over every joint of the file, before removals (robosuite applies its defaults
        # before removing actuation, so GR1ArmsOnly keeps the armature of its original indices).
        names = self.source.joint_names
        pristine = {j.name: j for j in self.source.pristine.joints}
        in_file = [{a: joint_attribute(pristine[n], a) for a in SETTABLE_JOINT_ATTRIBUTES} for n in names]
        authored_by_name = dict(
            zip((j.name for j in self.source.pristine.joints), self.source.authored, strict=True)
        )
        authored = [authored_by_name[n] for n in names]
        table = apply_default_rules(names, in_file, authored, self.spec.joint_defaults, self.locate)
        table = {name: values for name, values in table.items() if name in self._joint_names}
        for index, added in enumerate(getattr(self.spec, "added_joints", [])):
            source = f"spec added_joints[{index}]"
            values = {a: float(getattr(added, a)) for a in JOINT_RULE_ATTRIBUTES}
            table[added.name] = {a: JointValue(value, source) for a, value in values.items()}
        apply_overrides(table, self._joint_names, self.spec.joints, self.locate)
        return table

    def _check_init_qpos(self) -> None:
        init_qpos = self.spec.init_qpos
        if init_qpos is not None and len(init_qpos) != self.dof_joints:
            raise SpecError(
                self.spec_problem(
                    ("init_qpos",),
                    f"expected {self.dof_joints} values (one per joint: "
                    f"{summarize_names(self._joint_names)}), got {len(init_qpos)}",
                )
            )

    def part_spec(self) -> mujoco.MjSpec:
        """A fresh copy of the prepared spec, with joint values and collision colours applied."""
        spec = self.prepared.copy()
        for name, values in self.joint_values.items():
            joint = spec.joint(name)
            for attribute, joint_value in values.items():
                set_joint_attribute_value(joint, attribute, joint_value.value)
        for geom in spec.geoms:
            if geom.group == COLLISION_GROUP:  # robosuite's convention: collision geoms in group 0
                geom.rgba = self.collision_rgba
                geom.material = ""
        return spec

    def compile_alone(self) -> mujoco.MjModel:
        """Compile this part on its own (as ``assembler validate --compile`` does for bases and grippers)."""
        assembly = compose.new_assembly(self.source.globals_xml)
        compose.attach_at_world(assembly, self.part_spec(), self.naming_prefix)
        self._complete_alone(assembly)
        require_kept_alone(self, assembly)
        where = self.loaded.source if self.loaded is not None else type(self).__qualname__
        return compile_with_home(
            assembly, self.home_qpos(), f"{where}: {self.family} '{type(self).__name__}'"
        )

    def _complete_alone(self, assembly: mujoco.MjSpec) -> None:
        """What a part needs around it to compile on its own; nothing for most parts."""

    # ----- names --------------------------------------------------------------------------

    @property
    def naming_prefix(self) -> str:
        """Prefix of every element name of this part."""
        raise NotImplementedError

    @property
    def name(self) -> str:
        """The instance's name, ``{ClassName}{idn}`` as in robosuite."""
        return f"{type(self).__name__}{self.idn}"

    def prefixed(self, names: list[str]) -> list[str]:
        """``names`` with this part's prefix."""
        return [self.naming_prefix + name for name in names]

    @property
    def root_name(self) -> str:
        """The root body as named in the MJCF."""
        return self._root_name

    @property
    def root_body(self) -> str:
        """The part's root body (prefixed)."""
        return self.naming_prefix + self.root_name

    @property
    def joints(self) -> list[str]:
        """The part's joints (prefixed), MuJoCo's order; free joints are not counted."""
        return self.prefixed(self._joint_names)

    @property
    def dof_joints(self) -> int:
        """Number of the part's joints (a ball joint counts once, a free joint not at all)."""
        return len(self._joint_names)

    @property
    def actuators(self) -> list[str]:
        """The part's actuators (prefixed), in file order."""
        return self.prefixed([a.name for a in self.prepared.actuators if a.name])

    @property
    def sensors(self) -> list[str]:
        """The part's named sensors (prefixed)."""
        return self.prefixed([s.name for s in self.prepared.sensors if s.name])

    @property
    def sites(self) -> list[str]:
        """The part's named sites (prefixed)."""
        return self.prefixed([s.name for s in self.prepared.sites if s.name])

    @property
    def bodies(self) -> list[str]:
        """The part's named bodies (prefixed), root first."""
        return self.prefixed([b.name for b in self.prepared.bodies[1:] if b.name])

    def _geoms_in_group(self, group: int) -> list[str]:
        return self.prefixed([g.name for g in self.prepared.geoms if g.group == group and g.name])

    @property
    def contact_geoms(self) -> list[str]:
        """The part's named collision geoms (group 0, robosuite's convention)."""
        return self._geoms_in_group(COLLISION_GROUP)

    @property
    def visual_geoms(self) -> list[str]:
        """The part's named visual geoms (group 1, robosuite's convention)."""
        return self._geoms_in_group(VISUAL_GROUP)

    @property
    def contact_geom_rgba(self) -> list[float]:
        """Colour given to the part's collision geoms."""
        return list(self.collision_rgba)

    @property
    def init_qpos(self) -> FloatArray:
        """Initial joint positions, one per joint (the MJCF's qpos0 when the spec gives none)."""
        if self.spec.init_qpos is not None:
            return np.array(self.spec.init_qpos, dtype=float)
        return np.array([self.prepared.joint(n).ref for n in self._joint_names], dtype=float)

    def home_qpos(self) -> dict[str, float]:
        """Prefixed joint name -> initial position, for the ``home`` keyframe."""
        if self.spec.init_qpos is None:
            return {}
        return dict(zip(self.joints, self.spec.init_qpos, strict=True))

    def __repr__(self) -> str:
        return f"<{type(self).__name__} idn={self.idn!r} prefix={self.naming_prefix!r}>"
