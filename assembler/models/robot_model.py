"""RobotModel: one robot's MJCF under its ``robot{idn}_`` prefix, with its joint rules applied.

A robot class carries a validated :class:`RobotSpec` (``spec``); each instance loads a private
copy of the spec's MJCF, prefixes every name through MjSpec, resolves the joint parameters (file,
rules, overrides) with their sources, and recolours collision geoms as robosuite does. Name lists
are read from the live assembly, so they cannot go stale after later edits.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path
from typing import TYPE_CHECKING, Any, ClassVar

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.errors import (
    AssemblerError,
    JointAttributeError,
    Location,
    MjcfError,
    Problem,
    SpecError,
    summarize_names,
)
from assembler.mjcf.assembly import prefixed_spec, root_body_name
from assembler.mjcf.emit import to_xml, write_atomically
from assembler.mjcf.keyframe import compile_with_home
from assembler.mjcf.source import MjcfSource, load_mjcf
from assembler.models.joint_rules import (
    JointTable,
    JointValue,
    apply_default_rules,
    apply_overrides,
)
from assembler.registry import RobotModelMeta
from assembler.schema import RobotSpec
from assembler.yaml_source import DataPath

if TYPE_CHECKING:
    from assembler.loader import LoadedSpec

ROBOT_COLLISION_COLOR: tuple[float, float, float, float] = (0.0, 0.5, 0.0, 1.0)
"""robosuite's colour for a robot's collision geoms (group 0)."""

SETTABLE_JOINT_ATTRIBUTES: tuple[str, ...] = ("frictionloss", "damping", "armature", "stiffness")
"""Attributes ``set_joint_attribute`` accepts: the ones whose MJCF origin the assembler tracks."""

COLLISION_GROUP = 0
VISUAL_GROUP = 1

FloatArray = NDArray[np.float64]


def _joint_attribute(joint: mujoco.MjsJoint, attribute: str) -> float:
    value = getattr(joint, attribute)
    return float(value[0]) if hasattr(value, "__len__") else float(value)


def _set_joint_attribute(joint: mujoco.MjsJoint, attribute: str, value: float) -> None:
    if attribute in ("damping", "stiffness"):  # polynomial coefficients since MuJoCo 3.7
        coefficients = np.array(getattr(joint, attribute), dtype=float)
        coefficients[0] = value
        setattr(joint, attribute, coefficients)
    else:
        setattr(joint, attribute, value)


def _euler_to_quat(rpy: FloatArray) -> FloatArray:
    """(w, x, y, z) of the rotation Rz(yaw) Ry(pitch) Rx(roll), robosuite's ``set_base_ori`` convention."""
    quat = np.zeros(4)
    mujoco.mju_euler2Quat(quat, np.asarray(rpy, dtype=float), "XYZ")
    return quat


class RobotModel(metaclass=RobotModelMeta):
    """A robot built from its spec: prefixed MJCF, joint rules, placement, and compilation."""

    abstract = True

    spec: ClassVar[RobotSpec]
    """The validated spec this class was made from."""

    loaded: ClassVar[LoadedSpec | None] = None
    """The spec's file and positions, for pointing errors at the line that caused them."""

    def __init__(self, idn: int | str = 0) -> None:
        self.idn = idn
        self.source: MjcfSource = self._load_source()
        self._root_name = root_body_name(self.source)
        self.mjspec: mujoco.MjSpec = prefixed_spec(self.source, self.naming_prefix)
        self.base: Any = None
        self.mujoco_model: mujoco.MjModel | None = None
        self.joint_values: JointTable = self._resolve_joint_values()
        self._write_joint_values()
        self._recolor_collision_geoms()
        self._check_init_qpos()

    # ----- construction -------------------------------------------------------------------

    def _locate(self, path: DataPath) -> Location:
        if self.loaded is not None:
            return self.loaded.location(path)
        return Location(f"<class {type(self).__qualname__}>")

    def _load_source(self) -> MjcfSource:
        try:
            return load_mjcf(self.spec.mjcf)
        except MjcfError as error:
            where = self._locate(("mjcf",))
            raise MjcfError([Problem(p.message, where, "mjcf") for p in error.problems]) from None

    def _resolve_joint_values(self) -> JointTable:
        names = self.source.joint_names
        joints = [self.mjspec.joint(self.naming_prefix + n) for n in names]
        in_file = [{a: _joint_attribute(j, a) for a in SETTABLE_JOINT_ATTRIBUTES} for j in joints]
        authored_by_name = dict(
            zip((j.name for j in self.source.pristine.joints), self.source.authored, strict=True)
        )
        authored = [authored_by_name[n] for n in names]
        table = apply_default_rules(names, in_file, authored, self.spec.joint_defaults, self._locate)
        apply_overrides(table, names, self.spec.joints, self._locate)
        return table

    def _write_joint_values(self) -> None:
        for name, values in self.joint_values.items():
            joint = self.mjspec.joint(self.naming_prefix + name)
            for attribute, joint_value in values.items():
                _set_joint_attribute(joint, attribute, joint_value.value)

    def _recolor_collision_geoms(self) -> None:
        """robosuite's convention: collision geoms (group 0) drawn in the robot's contact colour."""
        for geom in self.mjspec.geoms:
            if geom.group == COLLISION_GROUP:
                geom.rgba = self.contact_geom_rgba
                geom.material = ""

    def _check_init_qpos(self) -> None:
        init_qpos = self.spec.init_qpos
        if init_qpos is not None and len(init_qpos) != self.dof:
            raise SpecError(
                Problem(
                    f"expected {self.dof} values (one per joint: "
                    f"{summarize_names(self.source.joint_names)}), got {len(init_qpos)}",
                    self._locate(("init_qpos",)),
                    "init_qpos",
                )
            )

    # ----- names --------------------------------------------------------------------------

    @property
    def naming_prefix(self) -> str:
        """Prefix of every element name of this robot: ``robot{idn}_``."""
        return f"robot{self.idn}_"

    @property
    def name(self) -> str:
        """The instance's name, ``{ClassName}{idn}`` as in robosuite (e.g. ``Sparrow70``)."""
        return f"{type(self).__name__}{self.idn}"

    def _prefixed(self, names: list[str]) -> list[str]:
        return [self.naming_prefix + name for name in names]

    def _own(self, elements: list[Any]) -> list[str]:
        """Names of the robot's own elements among ``elements`` (bases and grippers excluded)."""
        prefix = self.naming_prefix
        return [e.name for e in elements if e.name.startswith(prefix)]

    @property
    def root_body(self) -> str:
        """The robot's root body (prefixed)."""
        return self.naming_prefix + self._root_name

    @property
    def bodies(self) -> list[str]:
        """All of the robot's bodies (prefixed), root first."""
        return self._own(self.mjspec.bodies[1:])

    @property
    def joints(self) -> list[str]:
        """The robot's own joints (prefixed), MuJoCo's order; free joints are not robot DoFs."""
        return self._prefixed(self.source.joint_names)

    @property
    def dof(self) -> int:
        """Number of the robot's own joints (not nq or nv: a ball joint counts once)."""
        return len(self.source.joint_names)

    @property
    def actuators(self) -> list[str]:
        """The robot's own actuators (prefixed), in file order."""
        return self._prefixed([a.name for a in self.source.pristine.actuators if a.name])

    @property
    def cameras(self) -> list[str]:
        """Every named camera in the assembly (prefixed), including those of attached parts."""
        return [c.name for c in self.mjspec.cameras if c.name]

    @property
    def sites(self) -> list[str]:
        """The robot's own named sites (prefixed)."""
        return self._own(self.mjspec.sites)

    @property
    def sensors(self) -> list[str]:
        """The robot's own named sensors (prefixed)."""
        return self._own(self.mjspec.sensors)

    def _geoms_in_group(self, group: int) -> list[str]:
        prefix = self.naming_prefix
        return [g.name for g in self.mjspec.geoms if g.group == group and g.name.startswith(prefix)]

    @property
    def contact_geoms(self) -> list[str]:
        """The robot's named collision geoms (group 0, robosuite's convention)."""
        return self._geoms_in_group(COLLISION_GROUP)

    @property
    def visual_geoms(self) -> list[str]:
        """The robot's named visual geoms (group 1, robosuite's convention)."""
        return self._geoms_in_group(VISUAL_GROUP)

    @property
    def contact_geom_rgba(self) -> list[float]:
        """Colour given to collision geoms: robosuite's ``ROBOT_COLLISION_COLOR``."""
        return list(ROBOT_COLLISION_COLOR)

    @property
    def models(self) -> list[Any]:
        """Sub-models attached to this robot (its base, when it has one)."""
        return [self.base] if self.base is not None else []

    @property
    def all_joints(self) -> list[str]:
        """The robot's joints followed by its base's joints."""
        return self.joints + (list(self.base.joints) if self.base is not None else [])

    @property
    def all_actuators(self) -> list[str]:
        """The robot's actuators followed by its base's actuators."""
        return self.actuators + (list(self.base.actuators) if self.base is not None else [])

    # ----- spec fields --------------------------------------------------------------------

    @property
    def default_base(self) -> str | None:
        """Name of the base the robot is assembled with by default."""
        return self.spec.default_base

    @property
    def default_controller_config(self) -> dict[str, str]:
        """Controller config name per body part."""
        return dict(self.spec.default_controller_config)

    @property
    def init_qpos(self) -> FloatArray:
        """Initial joint positions, one per robot joint (the MJCF's qpos0 when the spec gives none)."""
        if self.spec.init_qpos is not None:
            return np.array(self.spec.init_qpos, dtype=float)
        refs = [self.mjspec.joint(name).ref for name in self.joints]
        return np.array(refs, dtype=float)

    @property
    def base_xpos_offset(self) -> dict[str, Callable[..., FloatArray]]:
        """Per arena, a function of the arena's variables (``table_length=...``) giving the offset."""

        def offset(arena: str) -> Callable[..., FloatArray]:
            return lambda **variables: np.array(self.spec.resolve_base_xpos_offset(arena, **variables))

        return {arena: offset(arena) for arena in self.spec.base_xpos_offset}

    @property
    def top_offset(self) -> FloatArray:
        """Offset from the robot's root to its top (metres)."""
        return np.array(self.spec.top_offset, dtype=float)

    @property
    def _horizontal_radius(self) -> float:
        return self.spec.horizontal_radius

    @property
    def horizontal_radius(self) -> float:
        """Footprint radius (metres); the base's, if larger."""
        if self.base is None:
            return self._horizontal_radius
        return max(self._horizontal_radius, float(self.base.horizontal_radius))

    @property
    def base_offset(self) -> FloatArray:
        """The root body's position as the MJCF writes it (robosuite's ``_base_offset``)."""
        return np.array(self.source.pristine.body(self._root_name).pos, dtype=float)

    @property
    def bottom_offset(self) -> FloatArray:
        """Vector from the root body to the bottom of the robot (and of its base, when it has one)."""
        if self.base is None:
            return self.base_offset
        base_bottom: FloatArray = np.asarray(self.base.bottom_offset, dtype=float)
        base_top: FloatArray = np.asarray(self.base.top_offset, dtype=float)
        return base_bottom - base_top + self.base_offset

    # ----- placement and joints -----------------------------------------------------------

    def set_base_xpos(self, pos: FloatArray) -> None:
        """Place the robot so that its bottom is at ``pos`` (x, y, z in metres)."""
        position = np.asarray(pos, dtype=float)
        if position.shape != (3,) or not np.all(np.isfinite(position)):
            raise AssemblerError(f"set_base_xpos: expected 3 finite numbers, got {pos!r}")
        self.mjspec.body(self.root_body).pos = position - self.bottom_offset

    def set_base_ori(self, rot: FloatArray) -> None:
        """Orient the robot by (roll, pitch, yaw) in radians, rotating about fixed x, y, z axes."""
        angles = np.asarray(rot, dtype=float)
        if angles.shape != (3,) or not np.all(np.isfinite(angles)):
            raise AssemblerError(f"set_base_ori: expected 3 finite angles, got {rot!r}")
        self.mjspec.body(self.root_body).quat = _euler_to_quat(angles)

    def set_joint_attribute(self, attrib: str, values: FloatArray, force: bool = True) -> None:
        """Set ``attrib`` on each robot joint; with ``force=False`` only where no value is set yet.

        As in robosuite, the rules have already given frictionloss, damping and armature to every
        joint, so ``force=False`` changes those only on joints whose rule is disabled in the spec.
        """
        if attrib not in SETTABLE_JOINT_ATTRIBUTES:
            raise JointAttributeError(
                f"set_joint_attribute: unsupported attribute '{attrib}'; "
                f"supported: {', '.join(SETTABLE_JOINT_ATTRIBUTES)}"
            )
        array = np.asarray(values, dtype=float).ravel()
        if array.size != self.dof:
            raise JointAttributeError(
                f"set_joint_attribute('{attrib}'): expected {self.dof} values (one per joint: "
                f"{summarize_names(self.joints)}), got {array.size}"
            )
        if not np.all(np.isfinite(array)) or np.any(array < 0):
            raise JointAttributeError(
                f"set_joint_attribute('{attrib}'): values must be finite and non-negative, got {array}"
            )
        for name, value in zip(self.source.joint_names, array, strict=True):
            if force or attrib not in self.joint_values[name]:
                self.joint_values[name][attrib] = JointValue(float(value), "set_joint_attribute")
                _set_joint_attribute(self.mjspec.joint(self.naming_prefix + name), attrib, float(value))

    # ----- compile and emit ---------------------------------------------------------------

    def home_qpos(self) -> dict[str, float]:
        """Joint name -> initial position for the ``home`` keyframe."""
        if self.spec.init_qpos is None:
            return {}
        return dict(zip(self.joints, self.spec.init_qpos, strict=True))

    def _what(self) -> str:
        where = self.loaded.source if self.loaded is not None else type(self).__qualname__
        return f"{where}: robot '{type(self).__name__}'"

    def get_model(self) -> mujoco.MjModel:
        """Compile the assembly (with its ``home`` keyframe) into a new ``mujoco.MjModel``."""
        return compile_with_home(self.mjspec, self.home_qpos(), self._what())

    def set_mujoco_model(self, mujoco_model: mujoco.MjModel | None = None) -> None:
        """Keep ``mujoco_model``, or compile one now."""
        self.mujoco_model = mujoco_model if mujoco_model is not None else self.get_model()

    def get_xml(self) -> str:
        """The assembly as one standalone MJCF document (compiled once first, so it is valid)."""
        self.get_model()
        return to_xml(self.mjspec)

    def save(self, path: str | Path) -> Path:
        """Write the MJCF to ``path`` atomically; nothing is written if compilation fails."""
        target = Path(path)
        write_atomically(target, self.get_xml())
        return target
