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

from assembler.documents.located import LocatedDocument
from assembler.errors import Location, Problem, SpecError, did_you_mean, summarize_names
from assembler.fieldpath import TOP, FieldPath
from assembler.paths import display_path, resolve_model_path

SPEC_SUFFIXES = (".yaml", ".yml")

NOT_INHERITED: tuple[str, ...] = ("name", "extends")
"""Fields a child never takes from its parent."""

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
    """The child's fields over the parent's: mappings merge key by key, anything else replaces."""
    data = copy.deepcopy({k: v for k, v in parent.data.items() if k not in NOT_INHERITED})
    fields = _without(parent.fields, NOT_INHERITED)
    values = _without(parent.values, NOT_INHERITED)

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
    return LocatedDocument(data=data, file=child.file, folder=child.folder, fields=fields, values=values)


def is_file_reference(reference: object) -> bool:
    """True for ``extends: ../robots/arm.yaml`` (a file), False for ``extends: Sparrow7`` (a name)."""
    return isinstance(reference, str) and (reference.endswith(SPEC_SUFFIXES) or "/" in reference)


class Resolver:
    """Resolves ``extends`` chains within a batch of documents and the registry, once each."""

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

    def resolve(self, document: LocatedDocument, chain: tuple[str, ...] = ()) -> LocatedDocument:
        """``document`` with its parents' fields merged in (itself when it extends nothing)."""
        if id(document) in self.done:
            return self.done[id(document)]
        reference = document.data.get("extends")
        if reference is None:
            return document
        where = document.where(EXTENDS)
        if not isinstance(reference, str) or not reference:
            raise SpecError(Problem("expected a spec name or a spec file path", where, EXTENDS))
        key = self._key(reference, document, where)
        own = str(document.data.get("name") or document.file)
        if key in chain or key == own:
            members = [*chain[chain.index(key) :], own] if key in chain else [own]
            start = members.index(min(members))  # one spelling per cycle, whichever file finds it
            members = members[start:] + members[:start]
            cycle = " -> ".join([*members, members[0]])
            raise SpecError(Problem(f"inheritance cycle: {cycle}; break it", where, EXTENDS))
        parent = self._parent(reference, key, where, document)
        merged = merge(self.resolve(parent, (*chain, own)), document)
        self.done[id(document)] = merged
        return merged

    def _key(self, reference: str, document: LocatedDocument, where: Location) -> str:
        """The parent's identity: an absolute file path, or a spec name."""
        if not is_file_reference(reference):
            return reference
        try:
            return str(Path(resolve_model_path(reference, document.folder)))
        except SpecError as error:  # a parent file outside the allowed folders
            raise SpecError([Problem(p.message, where, EXTENDS) for p in error.problems]) from None

    def _parent(self, reference: str, key: str, where: Location, child: LocatedDocument) -> LocatedDocument:
        if key != reference:  # a file
            path = Path(key)
            if not path.is_file():
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
