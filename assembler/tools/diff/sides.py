"""The two things ``assembler diff`` compares: each a spec file, a registered name or FILE@REV.

A side is loaded without registering it: two versions of one robot share a name, and neither
may replace the registered one. Its class is made the way the catalog makes registered classes,
but not registered (``in_registry = False``), and it is compiled the way
``assembler build`` compiles (robots with their default base and grippers; bases and grippers alone).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import mujoco

from assembler.errors import RegistryError, SpecError, did_you_mean, summarize_names
from assembler.files.paths import display_path, is_file
from assembler.files.regular import not_regular
from assembler.models import PartModel, RobotModel
from assembler.registry.catalog import PARENTS, class_from_spec
from assembler.registry.instances import equip
from assembler.registry.lookup import find_registered, registered_names
from assembler.spec.part_arguments import ArgumentKind, argument_kind
from assembler.spec.schema import PartSpec
from assembler.spec.spec_files import load_paths
from assembler.tools.diff.revision import load_at_revision, split_revision

DIFF_IDN = 0
"""Both sides are built as instance 0, so their element names match."""


@dataclass(frozen=True)
class Side:
    """One side of a diff: how the user named it, its validated spec, and the class it makes."""

    label: str
    part_class: type[PartModel]

    @property
    def spec(self) -> PartSpec:
        """The validated spec (``extends`` resolved)."""
        return self.part_class.spec

    def compile(self) -> mujoco.MjModel:
        """The compiled model: a robot with its default base and grippers, a base or gripper alone."""
        part = self.part_class(idn=DIFF_IDN)
        if not isinstance(part, RobotModel):
            return part.compile_alone()
        equip(part)
        return part.get_model()


def _registered(name: str) -> type[PartModel]:
    try:
        return find_registered(name)
    except RegistryError:
        pass
    names = registered_names()
    raise RegistryError(
        f"'{name}' is neither a spec file, FILE@REVISION nor a registered name.{did_you_mean(name, names)} "
        f"Registered: {summarize_names(names, limit=40)}"
    )


def load_side(reference: str) -> Side:
    """A side from a spec file, ``file@revision`` or a registered robot, base or gripper name."""
    revision = split_revision(reference)
    if revision is not None:
        return Side(reference, class_from_spec(load_at_revision(*revision), register=False))
    path = Path(reference)
    kind = argument_kind(reference)
    if kind is ArgumentKind.NAME:
        return Side(reference, _registered(reference))
    if kind is ArgumentKind.SPEC_FOLDER or not is_file(path):
        there = not_regular(path)  # a FIFO or a device is said for what it is
        what = f"{there}; give one spec file" if there is not None else "no such file"
        if kind is ArgumentKind.SPEC_FOLDER:
            what = "a folder; give one spec file"
        raise SpecError(f"{display_path(path)}: {what}")
    (loaded,) = load_paths([path], PARENTS)
    return Side(reference, class_from_spec(loaded, register=False))
