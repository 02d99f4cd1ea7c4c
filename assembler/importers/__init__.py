"""``assembler new``: a first spec for a vendor's MJCF or URDF, written so that it validates and builds
as it stands, every guess commented and every open question named with the field to set.

The file is read by the readers a spec uses (:mod:`~assembler.importers.reading`); the kinematic
tree gives the arm, its joints and end-effector (:mod:`~assembler.importers.tree`); the compiled
model gives a home pose and torque limits (:mod:`~assembler.importers.physics`);
:mod:`~assembler.importers.decisions` turns them into fields, :mod:`~assembler.importers.entries`
into YAML. Nothing in the vendor's files is changed.
"""

from __future__ import annotations

import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Literal

from assembler.errors import AssemblerError
from assembler.files.menagerie import MENAGERIE_SCHEME
from assembler.files.paths import PACKAGE_SCHEME, display_path
from assembler.files.repositories import MARKER
from assembler.files.writing import write_atomically
from assembler.importers.actuator_fixes import actuator_fixes, fixes_entry
from assembler.importers.decisions import Jaw, robot_entries
from assembler.importers.entries import Entry, spec_text
from assembler.importers.hands import gripper_entries
from assembler.importers.jaws import jaw_entries, jaw_of, jaws_of
from assembler.importers.legged import legged_entries
from assembler.importers.naming import camel_case, free_name, name_source
from assembler.importers.packages import BesidePackage, declaration, found_packages, packages_beside
from assembler.importers.reading import (
    ModelFile,
    check_model_path,
    file_format,
    read_model_file,
    spec_reference,
)
from assembler.importers.robosuite_names import robosuite_names
from assembler.importers.scene import scene_cut, scene_entry
from assembler.importers.tree import Tree, read_tree
from assembler.importers.wheels import base_entries, is_wheeled_base
from assembler.registry.catalog import load_shipped_specs
from assembler.registry.lookup import registered_names

Kind = Literal["robot", "gripper", "base"]

HAND_WORDS = re.compile(r"hand|gripper", re.IGNORECASE)
"""Words in a file's model name, file name or folder that make it a gripper rather than an arm."""

NAME_ENDINGS: dict[str, str] = {"robot": "Arm", "gripper": "Hand", "base": "Base"}
"""What ends a spec's name when the file's name is taken already."""

ARM_WITH_HAND = re.compile(r"with_?(hand|gripper)", re.IGNORECASE)
"""Words that say the file is an arm carrying its hand (``xarm6_with_gripper.urdf``)."""

__all__ = ["NewSpec", "new_spec", "snake_case", "write_new_spec", "write_spec_and_jaws"]


@dataclass(frozen=True)
class NewSpec:
    """A written spec: its text, registry name and kind."""

    text: str
    name: str
    kind: Kind
    packages: tuple[BesidePackage, ...] = ()
    """ROS packages the URDF names that only a folder beside it holds, and what the user adds."""
    jaws: tuple[NewSpec, ...] = ()
    """The gripper specs of the jaws cut from an arm's file (:mod:`~assembler.importers.jaws`): one of a
    one-arm robot, one per hand of a bimanual robot (right first); each written beside the robot's spec
    (:meth:`jaw_paths`)."""

    def jaw_paths(self, spec_path: Path) -> tuple[Path, ...]:
        """Where the jaws' specs go when the robot's goes to ``spec_path``: beside it, each named after
        its spec."""
        return tuple(spec_path.with_name(snake_case(jaw.name) + ".yaml") for jaw in self.jaws)


def _kind(file: ModelFile) -> tuple[Kind, str]:
    words = " ".join([file.source.pristine.modelname, file.path.stem, file.path.parent.name])
    found = None if ARM_WITH_HAND.search(words) else HAND_WORDS.search(words)
    if found:
        return "gripper", f"'{found.group(0)}' in the file's model name, file name or folder"
    return "robot", "no 'hand' or 'gripper' in the file's model name, file name or folder"


def _header(file: ModelFile) -> list[str]:
    return [
        "Written by `assembler new` from this file, which it did not change:",
        f"  {display_path(file.path)}",
        "'guess:' marks a value read off the file (check it); 'decide:' marks what the file cannot tell",
        "(set the field it names). docs/add-your-robot.md explains each.",
    ]


def _file_entry(file: ModelFile, spec_path: Path) -> Entry:
    """``mjcf:`` or ``urdf:``, with what stops the file from being one robot, if anything."""
    entry = Entry(file.format, spec_reference(file, spec_path.parent))
    model = file.model
    roots = [model.body(b).name for b in range(1, model.nbody) if model.body_parentid[b] == 0]
    if len(roots) > 1:
        entry.decide(
            f"this file is a scene: its <worldbody> holds {len(roots)} bodies ({', '.join(roots)}) that "
            "mjcf_fixes could not cut down to one; a spec's file holds one robot under one root body: "
            "point it at a file of the robot alone"
        )
    if not spec_reference(file, spec_path.parent).startswith(
        (PACKAGE_SCHEME, MENAGERIE_SCHEME)
    ) and not _below(file.path, spec_path.parent):
        entry.decide(
            "the file is outside the spec's folder, which a spec may not read by default: move the spec "
            "beside it, declare a spec repository, or pass --allow-path (SECURITY.md)"
        )
    return entry


def _package_notes(entry: Entry, packages: list[BesidePackage]) -> Entry:
    for package in packages:
        if package.declared == "beside the spec":
            entry.guess(package.todo)
        else:
            entry.decide(package.todo)
    return entry


def _below(path: Path, folder: Path) -> bool:
    return path.resolve().is_relative_to(folder.resolve())


def new_spec(model_path: Path, spec_path: Path, kind: Kind | None = None, strict: bool = False) -> NewSpec:
    """The spec for the MJCF or URDF at ``model_path``, to be written at ``spec_path`` (file references
    are relative to its folder); ``kind`` robot or gripper, guessed when None; ``strict``: a file read
    only with a repair or with values left out is refused (:func:`~assembler.importers.reading.repairs`)."""
    resolved = check_model_path(model_path)  # before the URDF's packages are looked for in it
    packages = packages_beside(resolved, spec_path.parent) if file_format(model_path) == "urdf" else []
    with found_packages(packages):
        file = read_model_file(model_path, strict=strict)
    cut = None
    fixes = []
    if file.format == "mjcf":
        cut = scene_cut(file.path, frozenset(Path(p) for p, _, _ in file.source.files), file.model)
        if cut is not None and cut.cuts:
            fixes = cut.fixes
            file = read_model_file(model_path, fixes)
    guessed_kind, why = _kind(file)
    tree = read_tree(file.model, hand=(kind or guessed_kind) == "gripper")
    if guessed_kind == "robot" and is_wheeled_base(tree):
        guessed_kind, why = "base", "wheels and neither arm nor feet"
    chosen: Kind = kind or guessed_kind
    repaired = []
    if file.format == "mjcf":  # read again with them: the jaw's cut and the arm's drive read the names
        repaired = actuator_fixes(
            file, fixes, tree.arm_joints if chosen == "robot" and tree.limbs is None else ()
        )
        if repaired:
            file = read_model_file(model_path, [*fixes, *(each.fix for each in repaired)])
    load_shipped_specs()
    source = name_source(file.source.pristine.modelname, file.path, scene=cut is not None)
    taken = {*registered_names(), *robosuite_names()}
    name = free_name(camel_case(source), taken, NAME_ENDINGS[chosen])
    named = Entry("name", name).guess(f"from '{source}'; the registry and class name, yours to choose")
    if name != camel_case(source):
        named.guess(f"{camel_case(source)} is the name of a registered spec or of a robosuite class already")
    entries: list[Entry] = []
    if chosen != "robot":
        kind_entry = Entry("kind", chosen)
        if kind is None:
            kind_entry.guess(f"{why}; a robot: delete this line (or run assembler new --kind robot)")
        entries.append(kind_entry)
    entries += [
        named,
        Entry("description", f"{source} from {Path(file.reference).name}, as `assembler new` read it."),
        _package_notes(_file_entry(file, spec_path), packages),
    ]
    file_fixes = fixes_entry(scene_entry(cut) if cut is not None else None, repaired)
    entries += [file_fixes] if file_fixes is not None else []
    jaws: dict[str, Jaw] = {}
    if chosen == "gripper":
        entries += gripper_entries(file, tree)
    elif chosen == "base":
        entries += base_entries(file, tree)
    elif tree.limbs is not None:
        entries += legged_entries(file, tree)
    else:
        jaws = _jaws(file, tree, name, {*taken, name})
        entries += robot_entries(file, tree, jaws)
    if chosen == "robot" and kind is None:
        what = "a robot with feet" if tree.limbs is not None else "a robot arm"
        entries[0].guess(f"{what}: {why}; a hand: assembler new --kind gripper")
    jaw_specs = []
    for side, jaw in jaws.items():
        which = f"{side} " if tree.arms else ""  # a bimanual robot's right or left
        jaw_fields = [
            Entry("kind", "gripper").guess(f"the jaw of {name}'s file, cut from the {which}arm"),
            Entry("name", jaw.name).guess(
                f"{name}'s {which}jaw; the registry and class name, yours to choose"
            ),
            Entry("description", f"The {which}jaw of {source}, from {Path(file.reference).name}."),
            _file_entry(file, spec_path),
        ]
        jaw_fixes = fixes_entry(None, [each for each in repaired if each.joint in jaw.joints])
        jaw_fields += [jaw_fixes] if jaw_fixes is not None else []
        grip_site = tree.arms[side].grip_site if tree.arms else tree.grip_site
        jaw_fields += jaw_entries(file, jaw, grip_site)
        jaw_specs.append(NewSpec(spec_text(_header(file), jaw_fields), jaw.name, "gripper"))
    return NewSpec(spec_text(_header(file), entries), name, chosen, tuple(packages), tuple(jaw_specs))


def _jaws(file: ModelFile, tree: Tree, name: str, taken: set[str]) -> dict[str, Jaw]:
    """The hands cut from the arms of ``name``'s file, by arm: a one-arm robot's jaw ``<name>Jaw``, a
    bimanual robot's ``<name>RightJaw`` and ``<name>LeftJaw`` (:mod:`~assembler.importers.jaws`)."""
    if not tree.arms:
        jaw = jaw_of(file.model, tree, free_name(f"{name}Jaw", taken, "Gripper"))
        return {} if jaw is None else {"right": jaw}
    names: dict[str, str] = {}
    for side in tree.arms:
        names[side] = free_name(f"{name}{side.title()}Jaw", {*taken, *names.values()}, "Gripper")
    return jaws_of(file.model, tree, names)


def snake_case(name: str) -> str:
    """``So101NewCalib`` -> ``so101_new_calib`` (the shipped specs' file names)."""
    return re.sub(r"(?<=[a-z0-9])(?=[A-Z])", "_", name).lower()


def write_new_spec(
    model_path: Path,
    spec_path: Path | None = None,
    kind: Kind | None = None,
    force: bool = False,
    strict: bool = False,
) -> tuple[NewSpec, Path]:
    """:func:`new_spec`, written to ``spec_path`` (default: ``<name in snake case>.yaml`` in the working
    folder); an existing file is kept unless ``force``. Returns the spec and where it was written."""
    written = new_spec(model_path, spec_path or Path.cwd() / "new.yaml", kind, strict)
    target = spec_path or Path(snake_case(written.name) + ".yaml")
    if os.path.lexists(target) and not force:  # a link too; a name too long is the writer's to say
        raise AssemblerError(f"{display_path(target)}: exists; keep it, or give --force to replace it")
    toml = declaration(written.packages)
    marker = target.parent / MARKER
    if toml is not None and os.path.lexists(marker):
        raise AssemblerError(
            f"{display_path(marker)}: exists; add what new would write to it: {toml.splitlines()[-1]}"
        )
    write_spec_and_jaws(written, target, force)
    if toml is not None:
        write_atomically(marker, toml)
    return written, target


def write_spec_and_jaws(written: NewSpec, target: Path, force: bool) -> None:
    """Write ``written`` to ``target`` and its jaws' specs beside it, if it has any: all or none; an
    existing jaw spec is kept unless ``force``."""
    jaw_targets = written.jaw_paths(target)
    for jaw_target in jaw_targets:
        if os.path.lexists(jaw_target) and not force:
            raise AssemblerError(
                f"{display_path(jaw_target)}: exists (the spec of {written.name}'s jaw goes there); keep "
                "it, or give --force to replace it"
            )
    try:
        for jaw_target, jaw in zip(jaw_targets, written.jaws, strict=True):
            write_atomically(jaw_target, jaw.text)
        write_atomically(target, written.text)
    except BaseException:
        for jaw_target in jaw_targets:  # no jaw spec without the robot's spec naming it
            jaw_target.unlink(missing_ok=True)
        raise
