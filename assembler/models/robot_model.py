"""RobotModel: a robot part plus the base it stands on, assembled into one prefixed MjSpec.

The assembly is a pure function of the parts (robot, base, grippers) and the robot's placement,
built afresh when a part is added; joint attributes and placement are also written into the
current assembly in place. Name lists come from the parts and the live assembly, so they cannot
go stale the way robosuite's ``_elements`` do after a mobile base is merged.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, ClassVar

import mujoco
import numpy as np

from assembler.cache import load_or_compile
from assembler.errors import AssemblerError, JointAttributeError, summarize_names
from assembler.mjcf import compose
from assembler.mjcf.emit import to_xml, write_atomically
from assembler.mjcf.keyframe import HOME_KEY, compile_with_home
from assembler.models.base_model import RobotBaseModel
from assembler.models.joint_rules import JointValue
from assembler.models.part import (
    SETTABLE_JOINT_ATTRIBUTES,
    FloatArray,
    PartModel,
    set_joint_attribute_value,
)
from assembler.schema import RobotSpec


def _euler_to_quat(rpy: FloatArray) -> FloatArray:
    """(w, x, y, z) of the rotation Rx(roll) Ry(pitch) Rz(yaw): robosuite's ``set_base_ori`` goes through
    ``transform_utils.euler2mat``, which builds that product (rotations about the moving x, y', z'')."""
    quat = np.zeros(4)
    mujoco.mju_euler2Quat(quat, np.asarray(rpy, dtype=float), "xyz")
    return quat


class RobotModel(PartModel):
    """A robot built from its spec: prefixed MJCF, joint rules, base, placement and compilation."""

    abstract = True
    family: ClassVar[str] = "robot"
    spec: ClassVar[RobotSpec]

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self.base: RobotBaseModel | None = None
        self.mujoco_model: mujoco.MjModel | None = None
        self._root_pos: FloatArray | None = None
        self._root_quat: FloatArray | None = None
        self._assembly: mujoco.MjSpec | None = None
        self._home_keyframe: tuple[FloatArray, FloatArray] | None = None
        self.use_cache = True
        """Whether ``get_model()`` may answer from the compiled-model cache (``--no-cache`` sets False)."""

    # ----- assembly -----------------------------------------------------------------------

    @property
    def mjspec(self) -> mujoco.MjSpec:
        """The assembly (robot, base, grippers) as a MuJoCo spec; rebuilt after ``add_*`` calls.
        Once built, ``get_model()`` compiles it as it is (it may have been edited), never from cache."""
        if self._assembly is None:
            self._assembly = self._new_assembly()
            if self._home_keyframe is not None:
                # The model came from the cache: its keyframe is what compiling this spec writes.
                key = self._assembly.add_key()
                key.name = HOME_KEY
                key.qpos, key.ctrl = (values.tolist() for values in self._home_keyframe)
        return self._assembly

    def _new_assembly(self) -> mujoco.MjSpec:
        assembly = compose.new_assembly(self.source.globals_xml)
        self.build_into(assembly)
        return assembly

    def build_into(self, assembly: mujoco.MjSpec) -> None:
        """Attach this robot, its base and its grippers to ``assembly`` (used for scenes too)."""
        robot = self.part_spec()
        base = self.base
        if base is None or base.type == "null":
            compose.attach_at_world(assembly, robot, self.naming_prefix)
            if base is not None:
                compose.add_sites_at_world(assembly, base.part_spec(), base.naming_prefix)
        elif base.type == "mount":
            compose.attach_at_world(assembly, robot, self.naming_prefix)
            compose.attach_mount(
                assembly, self.root_body, base.part_spec(), base.naming_prefix, self._base_placement(base)
            )
        else:
            compose.attach_robot_on_support(
                assembly,
                robot,
                self.naming_prefix,
                base.part_spec(),
                base.naming_prefix,
                base.spec.support_body,
                self._base_placement(base),
                legged=base.type == "legged",
            )
        self._attach_grippers(assembly)
        self._apply_placement(assembly)

    def _attach_grippers(self, assembly: mujoco.MjSpec) -> None:
        """Seam for ManipulatorModel."""

    def _base_placement(self, base: RobotBaseModel) -> FloatArray:
        # robosuite's rule (robot_model.py:161): the robot root's own MJCF position minus the
        # base's top offset, used as a position inside the robot root's frame.
        return self.base_offset - base.top_offset

    def _apply_placement(self, assembly: mujoco.MjSpec) -> None:
        root = assembly.body(self.root_body)
        if self._root_pos is not None:
            root.pos = self._root_pos
        if self._root_quat is not None:
            root.quat = self._root_quat

    def _rebuild(self) -> None:
        self._assembly = None
        self._home_keyframe = None

    def add_base(self, base: RobotBaseModel) -> None:
        """Merge ``base`` by its type: mount, mobile, legged or null. A second base is an error."""
        if self.base is not None:
            raise AssemblerError(
                f"{self.name} already has the base {self.base.name}; a robot stands on one base"
            )
        if not isinstance(base, RobotBaseModel):
            raise AssemblerError(f"add_base expects a base (create_base(...)), got {type(base).__name__}")
        self.base = base
        self._rebuild()

    # ----- names --------------------------------------------------------------------------

    @property
    def naming_prefix(self) -> str:
        """Prefix of every element name of this robot: ``robot{idn}_``."""
        return f"robot{self.idn}_"

    @property
    def dof(self) -> int:
        """Number of the robot's own joints (not nq or nv: a ball joint counts once)."""
        return self.dof_joints

    @property
    def cameras(self) -> list[str]:
        """Every named camera in the assembly (prefixed), including those of its base and grippers."""
        # A throwaway assembly when none is built yet, so reading names keeps the cache usable.
        assembly = self._assembly if self._assembly is not None else self._new_assembly()
        return [c.name for c in assembly.cameras if c.name]

    @property
    def models(self) -> list[PartModel]:
        """Sub-models attached to this robot: its base, then its grippers."""
        return [self.base] if self.base is not None else []

    @property
    def all_joints(self) -> list[str]:
        """The robot's joints followed by its base's joints."""
        return self.joints + (self.base.joints if self.base is not None else [])

    @property
    def all_actuators(self) -> list[str]:
        """The robot's actuators followed by its base's actuators."""
        return self.actuators + (self.base.actuators if self.base is not None else [])

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
    def base_xpos_offset(self) -> dict[str, Any]:
        """Per arena, a function of the arena's variables (``table_length=...``) giving the offset."""

        def offset(arena: str) -> Any:
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
        return max(self._horizontal_radius, self.base.horizontal_radius)

    @property
    def base_offset(self) -> FloatArray:
        """The root body's position as the MJCF writes it (robosuite's ``_base_offset``)."""
        return np.array(self.source.pristine.body(self.root_name).pos, dtype=float)

    @property
    def bottom_offset(self) -> FloatArray:
        """Vector from the root body to the bottom of the robot (and of its base, when it has one)."""
        if self.base is None:
            if self.spec.bottom_offset is not None:
                return np.array(self.spec.bottom_offset, dtype=float)
            return self.base_offset
        return self.base.bottom_offset - self.base.top_offset + self.base_offset

    # ----- placement and joints -----------------------------------------------------------

    def set_base_xpos(self, pos: FloatArray) -> None:
        """Place the robot so that its bottom is at ``pos`` (x, y, z in metres)."""
        position = np.asarray(pos, dtype=float)
        if position.shape != (3,) or not np.all(np.isfinite(position)):
            raise AssemblerError(f"set_base_xpos: expected 3 finite numbers, got {pos!r}")
        self._root_pos = position - self.bottom_offset
        if self._assembly is not None:
            self._apply_placement(self._assembly)

    def set_base_ori(self, rot: FloatArray) -> None:
        """Orient the robot by (roll, pitch, yaw) in radians as robosuite does: Rx(roll) Ry(pitch) Rz(yaw)."""
        angles = np.asarray(rot, dtype=float)
        if angles.shape != (3,) or not np.all(np.isfinite(angles)):
            raise AssemblerError(f"set_base_ori: expected 3 finite angles, got {rot!r}")
        self._root_quat = _euler_to_quat(angles)
        if self._assembly is not None:
            self._apply_placement(self._assembly)

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
        for name, value in zip(self._joint_names, array, strict=True):
            if force or attrib not in self.joint_values[name]:
                self.joint_values[name][attrib] = JointValue(float(value), "set_joint_attribute")
                if self._assembly is not None:  # otherwise the next build applies joint_values
                    joint = self._assembly.joint(self.naming_prefix + name)
                    set_joint_attribute_value(joint, attrib, float(value))

    # ----- compile and emit ---------------------------------------------------------------

    def assembly_home(self) -> dict[str, float]:
        """Joint -> initial position over the whole assembly: robot, base and grippers."""
        home = self.home_qpos()
        for part in self.models:
            home.update(part.home_qpos())
        return home

    def _what(self) -> str:
        where = self.loaded.source if self.loaded is not None else type(self).__qualname__
        return f"{where}: robot '{type(self).__name__}'"

    def get_model(self) -> mujoco.MjModel:
        """Compile the assembly (with its ``home`` keyframe) into a new ``mujoco.MjModel``; an unchanged
        robot comes from the compiled-model cache (assembler.cache) unless ``use_cache`` is False."""
        if self._assembly is not None or not self.use_cache:
            return compile_with_home(self.mjspec, self.assembly_home(), self._what())
        model = load_or_compile(
            self, lambda: compile_with_home(self._new_assembly(), self.assembly_home(), self._what())
        )
        home = mujoco.mj_name2id(model, mujoco.mjtObj.mjOBJ_KEY, HOME_KEY)
        self._home_keyframe = (model.key_qpos[home].copy(), model.key_ctrl[home].copy())
        return model

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
