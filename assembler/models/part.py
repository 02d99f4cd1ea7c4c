"""PartModel: what robots, bases and grippers share — a spec, its MJCF, joint values, a name prefix.

An instance reads its MJCF only when something needs it (a name list, a build, a check), so a
robot whose compiled model comes from the cache is never parsed. Once read, the part keeps a
private prepared copy of its MJCF (removals and additions applied) and its joint values with
their sources, and hands out fresh copies of the prepared spec to attach into an assembly.
"""

from __future__ import annotations

import json
import warnings
from collections.abc import Callable
from typing import Any, ClassVar

import mujoco
import numpy as np
from numpy.typing import NDArray

from assembler.cache.build_inputs import JointEdit, PartInputs
from assembler.compiler.compile import compile_home
from assembler.errors import AssemblerWarning, Location, MissingPackageError, MjcfError, Problem, SpecError
from assembler.files.paths import display_path, locate_model_file
from assembler.mjcf import COLLISION_GROUP, VISUAL_GROUP, census, compose
from assembler.mjcf.joints import set_joint_attribute_value
from assembler.mjcf.source import MjcfSource, load_mjcf
from assembler.models.actuator_table import ActuatorRecord
from assembler.models.collision_colour import collision_colour_note, colour_collision_geoms
from assembler.models.joint_rules import JointTable
from assembler.models.motor_table import MOTORS
from assembler.models.physical import PhysicalTable, apply_physical
from assembler.models.preparation import PreparedPart, init_qpos_problems, prepare
from assembler.models.registering import RegisteringMeta, Registry
from assembler.models.spec_names import NameCheck
from assembler.spec.documents import LoadedSpec
from assembler.spec.documents.problems import reading_order
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import PartSpec
from assembler.urdf import load_urdf, locate_urdf_file
from assembler.urdf.postprocess import unbalanced_inertias

FloatArray = NDArray[np.float64]

Adaptation = Callable[["PartModel", mujoco.MjSpec], mujoco.MjSpec]
"""A consumer's edit of a part's spec (see :attr:`PartModel.adaptation`)."""

_WARNED: dict[Any, Any] = {}
"""The warnings already shown (Python's registry for warn_explicit), so each is shown once."""


class PartModel(metaclass=RegisteringMeta):
    """A robot, base or gripper built from its spec."""

    in_registry = False
    family: ClassVar[str] = "part"
    registry: ClassVar[Registry[Any]]

    spec: ClassVar[PartSpec]
    """The validated spec this class was made from."""

    loaded: ClassVar[LoadedSpec[Any] | None] = None
    """The spec's file and positions, for pointing errors at the line that caused them."""

    collision_rgba: ClassVar[tuple[float, float, float, float]] = (0.0, 0.5, 0.0, 1.0)

    def __init__(self, idn: int | str = 0) -> None:
        self.idn = idn
        self.joint_edits: list[JointEdit] = []
        """``set_joint_attribute`` calls, in order (they are part of what the cache keys on)."""
        self.adaptation: Adaptation | None = None
        """The last edit of this part's spec for the one consumer it is made for, or None: the robosuite
        bridge's names and drives (:func:`assembler.robosuite.parts.robosuite_part`). Applied by
        :meth:`part_mjspec`, named in :meth:`part_inputs`."""
        self._prepared: PreparedPart | None = None

    # ----- the spec and its problems ----------------------------------------------------------

    @classmethod
    def locate(cls, path: FieldPath) -> Location:
        """The spec position of a field, for error messages."""
        if cls.loaded is not None:
            return cls.loaded.location(path)
        return Location(f"<class {cls.__qualname__}>")

    @classmethod
    def warn(cls, path: FieldPath, message: str) -> None:
        """Warn (an :class:`AssemblerWarning`) at a field of this part's spec: Python then shows the
        spec's file, line and text, not the line of our code that warned. Once per spec line and message."""
        where = cls.locate(path)
        warnings.warn_explicit(
            message, AssemblerWarning, where.file, where.line or 1, module=where.file, registry=_WARNED
        )

    @classmethod
    def spec_problem(cls, path: FieldPath, message: str) -> Problem:
        """A problem located at a field of this part's spec."""
        return Problem(message, cls.locate(path), FieldPath(path) or None)

    def _load_source(self) -> MjcfSource:
        field = FieldPath((self.spec.source_field,))
        try:
            if self.spec.urdf is not None:
                source = load_urdf(self.spec.urdf, self.spec.balance_inertia)
                self._refuse_unbalanced_inertias(source, field)
                return source
            return load_mjcf(self.spec.source_file, self.spec.mjcf_fixes)
        except MissingPackageError as error:
            located = [Problem(p.message, self.locate(field), field) for p in error.problems]
            raise MissingPackageError(located, error.package) from None
        except MjcfError as error:
            located = [Problem(p.message, self.locate(field), field) for p in error.problems]
            raise type(error)(located) from None

    def _refuse_unbalanced_inertias(self, source: MjcfSource, field: FieldPath) -> None:
        """A URDF whose link inertias MuJoCo would refuse at the assembly's compile, refused here at
        the spec's line with the spec's own remedy (MuJoCo's message names its ``balanceinertia``)."""
        unbalanced = unbalanced_inertias(source.pristine)
        if unbalanced:
            message = (
                f"{display_path(source.path)}: the inertia of link {', '.join(unbalanced)} violates "
                "A + B >= C, which MuJoCo refuses; set balance_inertia: true in the spec (each becomes "
                "isotropic at its mean moment, as MuJoCo's balanceinertia does), "
                "or correct the URDF's <inertia>"
            )
            raise MjcfError([Problem(message, self.locate(field), field)])

    def _name_problems(self, prepared: PreparedPart) -> list[Problem]:
        """Names the spec gives that its MJCF lacks; each family adds its own fields."""
        return init_qpos_problems(self.spec, prepared.joint_names, self.spec_problem)

    def name_check(self, prepared: PreparedPart) -> NameCheck:
        """A collector of name problems against this part's prepared MJCF."""
        return NameCheck(self.spec_problem, prepared.mjspec, prepared.joint_names)

    def prepared(self) -> PreparedPart:
        """The part's MJCF read and prepared (once); every problem of the spec against it at once."""
        if self._prepared is None:
            prepared, problems = prepare(self.spec, self._load_source(), self.spec_problem)
            problems += self._name_problems(prepared)
            if problems:
                raise SpecError(sorted(problems, key=reading_order))
            self._prepared = prepared
        return self._prepared

    def check(self) -> None:
        """Read the MJCF and check every name and count the spec gives against it (no compile)."""
        self.prepared()

    # ----- what the MJCF gives ----------------------------------------------------------------

    @property
    def source(self) -> MjcfSource:
        """The parsed MJCF file."""
        return self.prepared().source

    @property
    def prepared_mjspec(self) -> mujoco.MjSpec:
        """The MJCF's spec after the spec's removals and additions (read-only: use ``part_mjspec``)."""
        return self.prepared().mjspec

    @property
    def joint_values(self) -> JointTable:
        """Joint -> attribute -> value and source (the MJCF, a rule, an override, the API)."""
        return self.prepared().joint_values

    @property
    def actuator_table(self) -> list[ActuatorRecord]:
        """Every actuator of the part (unprefixed): the file's, then the spec's, with each value's source."""
        return self.prepared().actuators

    @property
    def physical(self) -> PhysicalTable:
        """Body -> mass and size factors, geom -> friction, with the spec entries that gave them."""
        return self.prepared().physical

    def part_mjspec(self) -> mujoco.MjSpec:
        """The spec this part attaches into an assembly: :meth:`own_mjspec`, then its ``adaptation``."""
        mjspec = self.own_mjspec()
        return mjspec if self.adaptation is None else self.adaptation(self, mjspec)

    def own_mjspec(self) -> mujoco.MjSpec:
        """A fresh copy of the prepared spec, with joint values, the ``bodies:``/``geoms:`` entries
        applied, and robosuite's collision colours where the spec asks for them
        (``collision_colour: robosuite``)."""
        mjspec = self.prepared_mjspec.copy()
        apply_physical(mjspec, self.physical)
        for name, values in self.joint_values.items():
            joint = mjspec.joint(name)
            for attribute, joint_value in values.items():
                set_joint_attribute_value(joint, attribute, joint_value.value)
        if self.spec.collision_colour == "robosuite":
            colour_collision_geoms(mjspec, self.collision_rgba)
        return mjspec

    def conventions_applied(self) -> list[str]:
        """What the part's build changes in its file's look by a convention the spec asks for."""
        robosuite = self.spec.collision_colour == "robosuite"
        return [collision_colour_note(self.collision_rgba)] if robosuite else []

    def part_inputs(self) -> PartInputs:
        """What this part contributes to an assembly's cache key (no MJCF is read)."""
        code: list[Any] = [*type(self).__mro__, *([self.adaptation] if self.adaptation is not None else [])]
        classes = tuple(f"{item.__module__}.{item.__qualname__}" for item in code)
        spec_made = all(
            cls is object or cls.__module__.startswith("assembler.") for cls in type(self).__mro__
        )
        reference = self.spec.source_file
        locate = locate_urdf_file if self.spec.urdf is not None else locate_model_file
        try:  # a URDF part's key names its URDF file the way an MJCF part's names its MJCF
            model_file = str(locate(reference))
        except MjcfError:
            model_file = reference  # the build says what is missing
        return PartInputs(
            family=self.family,
            classes=classes,
            spec_json=json.dumps(self._spec_data(), sort_keys=True),
            mjcf=model_file,
            idn=repr(self.idn),
            joint_edits=tuple(self.joint_edits),
            spec_made=spec_made,
        )

    def _spec_data(self) -> dict[str, Any]:
        """The spec as data, with the motor specs its ``motors:`` entries name: a changed motor spec
        changes the build."""
        data = self.spec.model_dump(mode="json")
        if self.spec.motors:
            data["motor_specs"] = MOTORS.inputs([entry.motor for entry in self.spec.motors])
        return data

    def describe(self) -> str:
        """How errors name this part: ``specs/x.yaml:1:1: gripper 'X'``."""
        where = self.loaded.source if self.loaded is not None else type(self).__qualname__
        return f"{where}: {self.family} '{type(self).__name__}'"

    def compile_alone(self) -> mujoco.MjModel:
        """Compile this part on its own (as ``assembler validate --compile`` does for bases and grippers)."""
        return self.compile_alone_spec()[0]

    def compile_alone_spec(self) -> tuple[mujoco.MjModel, mujoco.MjSpec]:
        """:meth:`compile_alone`, with the spec it compiled (its MJCF is ``spec.to_xml()``: ``assembler
        build`` of a gripper or base spec)."""
        assembly = compose.new_assembly(self.source.globals_xml)
        compose.attach_at_world(assembly, self.part_mjspec(), self.naming_prefix)
        self.complete_alone(assembly)
        what = f"building {self.family} '{type(self).__name__}' alone"
        census.require_at_least(census.of_spec(assembly), census.of_spec(self.prepared_mjspec), what)
        return compile_home(assembly, self.home_qpos(), self.describe()), assembly

    def complete_alone(self, assembly: mujoco.MjSpec) -> None:
        """What a part needs around it to compile on its own; nothing for most parts."""

    # ----- names ------------------------------------------------------------------------------

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
        return self.prepared().root_name

    @property
    def root_body(self) -> str:
        """The part's root body (prefixed)."""
        return self.naming_prefix + self.root_name

    @property
    def joint_names(self) -> list[str]:
        """The part's joints as named in its MJCF, MuJoCo's order; free joints are not counted."""
        return self.prepared().joint_names

    @property
    def joints(self) -> list[str]:
        """The part's joints (prefixed), MuJoCo's order; free joints are not counted."""
        return self.prefixed(self.joint_names)

    @property
    def dof_joints(self) -> int:
        """Number of the part's joints (a ball joint counts once, a free joint not at all)."""
        return len(self.joint_names)

    @property
    def actuators(self) -> list[str]:
        """The part's actuators (prefixed), in file order."""
        return self.prefixed([a.name for a in self.prepared_mjspec.actuators if a.name])

    @property
    def sensors(self) -> list[str]:
        """The part's named sensors (prefixed)."""
        return self.prefixed([s.name for s in self.prepared_mjspec.sensors if s.name])

    @property
    def sites(self) -> list[str]:
        """The part's named sites (prefixed)."""
        return self.prefixed([s.name for s in self.prepared_mjspec.sites if s.name])

    @property
    def bodies(self) -> list[str]:
        """The part's named bodies (prefixed), root first."""
        return self.prefixed([b.name for b in self.prepared_mjspec.bodies[1:] if b.name])

    def _geoms_in_group(self, group: int) -> list[str]:
        return self.prefixed([g.name for g in self.prepared_mjspec.geoms if g.group == group and g.name])

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
        return np.array([self.prepared_mjspec.joint(n).ref for n in self.joint_names], dtype=float)

    def home_qpos(self) -> dict[str, float]:
        """Prefixed joint name -> initial position, for the ``home`` keyframe."""
        if self.spec.init_qpos is None:
            return {}
        return dict(zip(self.joints, self.spec.init_qpos, strict=True))

    def __repr__(self) -> str:
        return f"<{type(self).__name__} idn={self.idn!r} prefix={self.naming_prefix!r}>"
