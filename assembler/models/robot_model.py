"""RobotModel: a robot part plus the base it stands on, built into one prefixed MjSpec.

Building is pure: :meth:`RobotModel.build_mjspec` makes a new assembly from the parts (robot, base,
grippers), their joint values and the robot's placement. Compiling belongs to the compile service
(:mod:`assembler.compiler.service`), which is given the build inputs and, only on a cache miss, the
build itself. Name lists come from the parts, so they cannot go stale the way robosuite's
``_elements`` do after a mobile base is merged.
"""

from __future__ import annotations

from functools import partial
from pathlib import Path
from typing import Any, ClassVar

import mujoco
import numpy as np

from assembler import compiler
from assembler.cache.build_inputs import BuildInputs, JointEdit
from assembler.compiler.compile import compile_and_emit, compile_home
from assembler.compiler.keyframe import Keyframe
from assembler.compiler.service import Assembly, CompiledModel, compile_model, compile_xml, entry_key
from assembler.errors import AssemblerError, JointAttributeError, Problem, summarize_names
from assembler.files.bundles import save_model
from assembler.mjcf import census, compose
from assembler.mjcf.census import Census
from assembler.mjcf.joints import set_joint_attribute_value
from assembler.models.bases import RobotBaseModel
from assembler.models.joint_rules import JointValue
from assembler.models.part import FloatArray, PartModel
from assembler.models.placement import PlacedPart
from assembler.models.preparation import SETTABLE_JOINT_ATTRIBUTES, PreparedPart
from assembler.models.provenance import API
from assembler.models.registering import REGISTRIES, Registry
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import RobotSpec

REGISTERED_ROBOTS: Registry[RobotModel] = REGISTRIES["robot"]
"""Every registered robot class by name, in registration order."""


class RobotModel(PlacedPart):
    """A robot built from its spec: prefixed MJCF, joint rules, base, placement and compilation."""

    in_registry = False
    family: ClassVar[str] = "robot"
    registry: ClassVar[Registry[Any]] = REGISTERED_ROBOTS
    spec: ClassVar[RobotSpec]

    def __init__(self, idn: int | str = 0) -> None:
        super().__init__(idn)
        self.mujoco_model: mujoco.MjModel | None = None
        self._keyframe: Keyframe | None = None
        self.entry_key: str | None = None
        """The compiled-model cache entry the last ``get_model``/``get_xml`` was answered from or
        stored under (None: not cached); a request records it rather than hashing the inputs again."""

    # ----- building -----------------------------------------------------------------------

    def build_mjspec(self) -> mujoco.MjSpec:
        """A new assembly of the robot, its base and grippers, placed; without keyframe, not compiled.
        Nothing of the parts is dropped in silence: a loss is a bug (``census.ElementsLost``)."""
        assembly = compose.new_assembly(self.source.globals_xml)
        before = census.of_spec(assembly)
        self.attach_into(assembly)
        census.require_growth(
            assembly, before, self.census_contribution(), f"building robot '{type(self).__name__}'"
        )
        return assembly

    def attach_into(self, assembly: mujoco.MjSpec) -> None:
        """Attach this robot, its base and its grippers to ``assembly``, placed, unchecked: a scene
        checks its robots' elements once for all of them (counting a spec's elements costs as much
        as the spec is large, so a check per robot of a growing scene would cost N² in its robots)."""
        robot = self.part_mjspec()
        if self.base is None:
            compose.attach_at_world(assembly, robot, self.naming_prefix)
        else:
            self.base.carry(assembly, robot, self.naming_prefix, self.base_offset - self.base.top_offset)
        self._attach_grippers(assembly)
        self._apply_placement(assembly)

    def census_contribution(self) -> Census:
        """How many elements of each kind building this robot with its base and grippers adds to an
        assembly: every element of every part (as prepared: what the specs remove is gone), except
        what the base's type changes."""
        total = census.of_spec(self.prepared_mjspec)
        if self.base is not None:
            total.update(self.base.census_contribution(self.prepared_mjspec.worldbody.first_body()))
        for gripper in getattr(self, "grippers", {}).values():
            total.update(census.of_spec(gripper.prepared_mjspec))
        return total

    def _attach_grippers(self, assembly: mujoco.MjSpec) -> None:
        """Seam for ManipulatorModel."""

    def build_inputs(self) -> BuildInputs:
        """What defines this assembly, for the compile service's cache key (no MJCF is read)."""
        grippers: dict[str, PartModel] = dict(getattr(self, "grippers", {}))

        def as_tuple(values: FloatArray | None) -> tuple[float, ...] | None:
            return None if values is None else tuple(float(v) for v in values)

        return BuildInputs(
            robot=self.part_inputs(),
            base=self.base.part_inputs() if self.base is not None else None,
            grippers=tuple((arm, gripper.part_inputs()) for arm, gripper in grippers.items()),
            root_pos=as_tuple(self._root_pos),
            root_quat=as_tuple(self._root_quat),
        )

    def _assembly(self) -> Assembly:
        """The built assembly and what the compile service needs with it."""
        parts = [self, *self.models]
        read = {path: (size, mtime) for part in parts for path, size, mtime in part.source.files}
        label = " + ".join(part.name for part in parts)
        return Assembly(self.build_mjspec(), self.assembly_home(), read, label, self.describe())

    def _changed(self) -> None:
        """A part was added: the next build starts afresh."""
        self._mjspec = None
        self._keyframe = None

    def add_base(self, base: RobotBaseModel) -> None:
        """Merge ``base`` by its type: mount, mobile, legged or null. A second base is an error."""
        if self.base is not None:
            raise AssemblerError(
                f"{self.name} already has the base {self.base.name}; a robot stands on one base"
            )
        if not isinstance(base, RobotBaseModel):
            raise AssemblerError(f"add_base expects a base (create_base(...)), got {type(base).__name__}")
        self.base = base
        self._changed()

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
        assembly = self._mjspec if self._mjspec is not None else self.build_mjspec()
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

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        check = self.name_check(prepared)
        groups = self.spec.joint_groups
        if groups is not None:
            for group in type(groups).model_fields:
                check.joint_patterns(FieldPath(("joint_groups", group)), getattr(groups, group))
        return [*super()._name_problems(prepared), *check.problems]

    # ----- spec fields --------------------------------------------------------------------

    @property
    def default_base(self) -> str | None:
        """Name of the base the robot is assembled with by default."""
        return self.spec.default_base

    @property
    def default_controller_config(self) -> dict[str, str]:
        """Controller config name per body part."""
        return dict(self.spec.default_controller_config)

    # ----- joints ------------------------------------------------------------------------

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
        self.joint_edits.append(JointEdit(attrib, tuple(float(v) for v in array), force))
        for name, value in zip(self.joint_names, array, strict=True):
            if force or attrib not in self.joint_values[name]:
                self.joint_values[name][attrib] = JointValue(float(value), API)
                if self._mjspec is not None:  # otherwise the next build applies joint_values
                    joint = self._mjspec.joint(self.naming_prefix + name)
                    set_joint_attribute_value(joint, attrib, float(value))

    # ----- compile and emit ---------------------------------------------------------------

    def assembly_home(self) -> dict[str, float]:
        """Joint -> initial position over the whole assembly: robot, base and grippers."""
        home = self.home_qpos()
        for part in self.models:
            home.update(part.home_qpos())
        return home

    @property
    def mjspec(self) -> mujoco.MjSpec:
        """The assembly (robot, base, grippers) as a MuJoCo spec, built on first use. Once you have
        it, ``get_model()`` compiles it as it is (you may have edited it), never from the cache."""
        if self._mjspec is None:
            self._mjspec = self.build_mjspec()
            if self._keyframe is not None:  # the model handed out earlier came with this keyframe
                self._keyframe.write(self._mjspec)
        return self._mjspec

    def get_model(self, cache: bool = True, store: bool = True) -> mujoco.MjModel:
        """Compile the assembly (with its ``home`` keyframe) into a new ``mujoco.MjModel``; an unchanged
        robot comes from the compiled-model cache unless ``cache`` is False, and a compiled one is
        kept there unless ``store`` is False."""
        if self._mjspec is not None:
            return compile_home(self._mjspec, self.assembly_home(), self.describe(), meshes=cache)
        self.entry_key = key = entry_key(self.build_inputs(), cache)
        patched = partial(self._patched, store) if key is not None else None
        compiled = compile_model(key, self._assembly, cache=cache, store=store, patched=patched)
        self._keyframe = compiled.keyframe
        return compiled.model

    def _patched(self, store: bool) -> CompiledModel | None:
        """On a cache miss: this robot patched from the cached model of the robot without its
        overrides (the model not stored; the patch kept unless ``store`` is False), or None to
        compile: the patcher the package root wired into the compiler
        (:data:`assembler.compiler.variant_patcher`), which reads the model classes."""
        if compiler.variant_patcher is None:
            return None
        answer: CompiledModel | None = compiler.variant_patcher().patched_variant(self, store)
        return answer

    def _patched_xml(self, cache: bool, store: bool) -> tuple[CompiledModel, str] | None:
        """On a cache miss: this robot's model and XML made from the model and XML of the robot without
        its overrides (not stored), or None to compile (see :meth:`_patched`). The plain robot's come
        from the cache, else from its compile, so the text written is the same whatever the cache holds."""
        if compiler.variant_patcher is None:
            return None
        patcher = compiler.variant_patcher()
        answer: tuple[CompiledModel, str] | None = patcher.patched_variant_xml(self, cache, store)
        return answer

    def set_mujoco_model(self, mujoco_model: mujoco.MjModel | None = None) -> None:
        """Keep ``mujoco_model``, or compile one now."""
        self.mujoco_model = mujoco_model if mujoco_model is not None else self.get_model()

    def get_xml(self, cache: bool = True, store: bool = True, meshes: bool = True) -> str:
        """The assembly as one standalone MJCF document (compiled once first, so it is valid); an
        unchanged robot's XML comes from the compiled-model cache, as its model does. ``meshes``
        False reads meshes from their files, not the mesh store (see ``compile_xml``)."""
        if self._mjspec is not None:  # the spec the user may have edited, as it is
            stored = cache and meshes
            model, xml = compile_and_emit(self._mjspec, self.assembly_home(), self.describe(), meshes=stored)
            self._keyframe = Keyframe.of(model)
            return xml
        self.entry_key = key = entry_key(self.build_inputs(), cache)
        patched = partial(self._patched_xml, cache, store)  # with the cache off too: one text either way
        compiled, xml = compile_xml(key, self._assembly, cache, store, meshes, patched)
        if compiled is not None:
            self._keyframe = compiled.keyframe
        return xml

    def save(self, path: str | Path, cache: bool = True) -> Path:
        """Write the MJCF to ``path`` atomically; nothing is written if compilation fails. Assets
        it names in the cache folder (meshes converted from COLLADA) are copied beside it, under
        ``FILE-assets/``, as ``assembler build -o`` does: the file loads after the cache is cleared."""
        return save_model(self.get_xml(cache=cache), Path(path))
