"""``extends:``: a spec document inherits every field its parent (a registered spec or a file) gives.

The child's fields are laid over the parent's: mappings merge key by key, anything else replaces.
Positions follow the data: a field the child writes points into the child's file, an inherited one
into the parent's. A batch of documents (a folder) resolves together, so its specs may extend one
another in any file order; cycles are named once, whatever their length.
"""

from __future__ import annotations

import copy
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any, Protocol

from assembler.errors import Location, Problem, SpecError, did_you_mean, summarize_names
from assembler.files.paths import display_path, is_file, resolve_model_path
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.fieldpath import TOP, FieldPath
from assembler.spec.part_arguments import SPEC_SUFFIXES

NOT_INHERITED: tuple[str, ...] = ("name", "extends")
"""Fields a child never takes from its parent."""

REPLACED_BY: dict[str, tuple[str, ...]] = {
    "urdf": ("mjcf", "mjcf_fixes"),
    "mjcf": ("urdf", "balance_inertia"),
}
"""A child's model file field -> the parent's fields it replaces: a spec names exactly one model
file (``mjcf`` or ``urdf``), and what repairs one kind of file does not follow it to the other."""

EXTENDS = FieldPath(("extends",))


class Parents(Protocol):
    """Where ``extends: <name>`` finds a parent outside the batch (the registry)."""

    def document(self, name: str) -> LocatedDocument | None:
        """The merged document of the spec registered as ``name``, if any."""

    def names(self, kind: str) -> list[str]:
        """The registered names of one spec kind (robot, base, gripper), for suggestions."""


class NoParents:
    """No registered specs: only the batch itself and files."""

    def document(self, name: str) -> LocatedDocument | None:
        return None

    def names(self, kind: str) -> list[str]:
        return []


def _without(marks: Mapping[FieldPath, Location], skipped: tuple[str, ...]) -> dict[FieldPath, Location]:
    return {path: mark for path, mark in marks.items() if not path or path[0] not in skipped}


def merge(parent: LocatedDocument, child: LocatedDocument) -> LocatedDocument:
    """The child's fields over the parent's: mappings merge key by key, anything else replaces
    (and a child's model file replaces the parent's of the other kind, see :data:`REPLACED_BY`)."""
    replaced = tuple(field for key, fields in REPLACED_BY.items() if key in child.data for field in fields)
    skipped = (*NOT_INHERITED, *replaced)
    data = copy.deepcopy({k: v for k, v in parent.data.items() if k not in skipped})
    fields = _without(parent.fields, skipped)
    values = _without(parent.values, skipped)

    def overlay(target: dict[str, Any], source: dict[str, Any], prefix: FieldPath) -> None:
        for key, value in source.items():
            here = prefix.child(key)
            if isinstance(value, dict) and isinstance(target.get(key), dict):
                overlay(target[key], value, here)
                continue
            for marks in (fields, values):
                for path in [p for p in marks if FieldPath(p).is_within(here)]:
                    del marks[path]
            target[key] = copy.deepcopy(value)
        for own, merged in ((child.fields, fields), (child.values, values)):
            for path, mark in own.items():
                if FieldPath(path).is_within(prefix) and len(path) > len(prefix):
                    merged.setdefault(path, mark)

    overlay(data, child.data, TOP)
    if TOP in child.fields:
        fields[TOP] = child.fields[TOP]
    return LocatedDocument(
        data=data,
        file=child.file,
        folder=child.folder,
        path=child.path,
        fields=fields,
        values=values,
        origins=tuple(dict.fromkeys((*child.origins, *parent.origins))),
    )


def is_file_reference(reference: object) -> bool:
    """True for ``extends: ../robots/arm.yaml`` (a file), False for ``extends: Sparrow7`` (a name)."""
    return isinstance(reference, str) and (reference.endswith(SPEC_SUFFIXES) or "/" in reference)


MAX_EXTENDS_DEPTH = 64
"""Longest chain of parents a spec may have: inheritance is a few levels deep."""


class Resolver:
    """Resolves ``extends`` chains within a batch of documents and the registry, once each.

    A chain is walked iteratively (no recursion, whatever its length); each document is known by
    its file (or its name when it has no file), so a cycle is found however it is written: by
    names, by file paths, or both.
    """

    def __init__(
        self,
        batch: dict[str, LocatedDocument],
        parents: Parents,
        read: Callable[[Path], LocatedDocument],
    ) -> None:
        """``batch``: documents by spec name; ``read``: reads a parent spec file into a document."""
        self.batch = batch
        self.parents = parents
        self.read = read
        self.done: dict[int, LocatedDocument] = {}

    def resolve(self, document: LocatedDocument) -> LocatedDocument:
        """``document`` with its parents' fields merged in (itself when it extends nothing)."""
        chain = [document]  # the document, its parent, its grandparent, ...
        while id(chain[-1]) not in self.done and chain[-1].data.get("extends") is not None:
            parent = self._parent(chain[-1])
            identities = [_identity(member) for member in chain]
            if _identity(parent) in identities:
                cycle = chain[identities.index(_identity(parent)) :]
                raise SpecError(Problem(_cycle_text(cycle), chain[-1].where(EXTENDS), EXTENDS))
            if len(chain) > MAX_EXTENDS_DEPTH:
                message = (
                    f"more than {MAX_EXTENDS_DEPTH} levels of extends; a spec inherits from a few parents"
                )
                raise SpecError(Problem(message, chain[-1].where(EXTENDS), EXTENDS))
            chain.append(parent)
        merged = self.done.get(id(chain[-1]), chain[-1])
        for child in reversed(chain[:-1]):
            merged = merge(merged, child)
            self.done[id(child)] = merged
        return merged

    def _parent(self, child: LocatedDocument) -> LocatedDocument:
        reference = child.data.get("extends")
        where = child.where(EXTENDS)
        if not isinstance(reference, str) or not reference:
            raise SpecError(Problem("expected a spec name or a spec file path", where, EXTENDS))
        if is_file_reference(reference):
            try:
                path = Path(resolve_model_path(reference, child.folder))
            except SpecError as error:  # a parent file outside the allowed folders
                raise SpecError([Problem(p.message, where, EXTENDS) for p in error.problems]) from None
            if not is_file(path):
                raise SpecError(Problem(f"parent spec file not found: {display_path(path)}", where, EXTENDS))
            return self.read(path)
        if reference in self.batch:
            return self.batch[reference]
        found = self.parents.document(reference)
        if found is None:
            raise SpecError(Problem(self._unknown(reference, child), where, EXTENDS))
        return found

    def _unknown(self, reference: str, child: LocatedDocument) -> str:
        kind = child.data.get("kind", "robot")
        kind = kind if isinstance(kind, str) else "robot"
        own_name = child.data.get("name")  # may be anything, e.g. a list: compare, never hash
        same_kind = [
            name
            for name, document in self.batch.items()
            if document.data.get("kind", "robot") == kind and name != own_name
        ]
        names = {*same_kind, *self.parents.names(kind)}
        if isinstance(own_name, str):
            names.discard(own_name)
        known = sorted(names)
        suggestion = did_you_mean(reference, known)
        if suggestion:
            return f"unknown {kind} spec '{reference}'.{suggestion}"
        return f"unknown {kind} spec '{reference}'. Known {kind}s: {summarize_names(known, limit=20)}"


def _identity(document: LocatedDocument) -> str:
    """What makes a document itself: its file, or (written as text) its name."""
    if document.path is not None:
        return str(document.path)
    return f"name:{document.data.get('name')!r}"


def _label(document: LocatedDocument) -> str:
    name = document.data.get("name")
    return name if isinstance(name, str) else document.file


def _cycle_text(cycle: list[LocatedDocument]) -> str:
    """``inheritance cycle: A -> B -> A; break it``, one spelling whichever member finds it."""
    members = [_label(member) for member in cycle]
    start = members.index(min(members))
    members = members[start:] + members[:start]
    return f"inheritance cycle: {' -> '.join([*members, members[0]])}; break it"
