"""Spec files -> validated spec objects (robots, bases, grippers), with file:line:col on every problem.

Loading is two steps per document: parse the YAML with positions (:mod:`assembler.yaml_source`),
then resolve ``extends:`` (a registered robot or another file) by merging the parent's fields
under the child's, and validate the result with the pydantic schema. A whole folder is loaded
together, so specs in it may extend one another in any file order, and every problem of every
file is reported at once.
"""

from __future__ import annotations

import copy
import types
import typing
from collections.abc import Callable, Iterable
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pydantic import BaseModel, ValidationError

from assembler.errors import AssemblerError, Location, Problem, SpecError, did_you_mean
from assembler.paths import confine, display_path, resolve_model_path
from assembler.schema import SPEC_KINDS, PartSpec
from assembler.yaml_source import DataPath, LocatedDocument, dotted, parse_yaml, read_yaml_text

SPEC_SUFFIXES = (".yaml", ".yml")

PATH_FIELDS: tuple[str, ...] = ("mjcf",)
"""Fields holding file references, resolved against the folder of the file that wrote them."""

NOT_INHERITED: tuple[str, ...] = ("name", "extends")


@dataclass(frozen=True)
class LoadedSpec:
    """A validated spec and the merged document it came from (for locating later problems)."""

    spec: PartSpec
    document: LocatedDocument

    @property
    def source(self) -> str:
        """Where the spec was written, as ``file:line:col`` of its first line."""
        return str(self.document.location(()))

    def location(self, path: DataPath) -> Location:
        """The position of a field's value (or of the closest enclosing field)."""
        return self.document.marks.get((*path, "<value>")) or self.document.location(path)


ParentLookup = Callable[[str], LocatedDocument | None]
"""Finds the merged document of a registered robot by name, for ``extends: <name>``."""


def _read_document(path: Path) -> LocatedDocument:
    shown = display_path(path)
    document = parse_yaml(read_yaml_text(path, shown), shown)
    _resolve_paths(document, path.parent.resolve())
    return document


def _resolve_paths(document: LocatedDocument, base_dir: Path | None) -> None:
    """Make file references absolute; each must stay in the spec's folder or a trusted one."""
    problems: list[Problem] = []
    for key in PATH_FIELDS:
        value = document.data.get(key)
        if isinstance(value, str) and value:
            try:
                document.data[key] = resolve_model_path(value, base_dir)
            except SpecError as error:
                where = document.marks.get((key, "<value>")) or document.location((key,))
                problems.extend(Problem(p.message, where, key) for p in error.problems)
    if problems:
        raise SpecError(problems)
    document.data.setdefault("__dir__", str(base_dir) if base_dir else None)


def _merge(parent: LocatedDocument, child: LocatedDocument) -> LocatedDocument:
    """The child's fields over the parent's: mappings merge key by key, anything else replaces."""
    data = copy.deepcopy({k: v for k, v in parent.data.items() if k not in NOT_INHERITED})
    marks = {path: mark for path, mark in parent.marks.items() if not path or path[0] not in NOT_INHERITED}

    def overlay(target: dict[str, Any], source: dict[str, Any], prefix: DataPath) -> None:
        for key, value in source.items():
            here = (*prefix, key)
            if isinstance(value, dict) and isinstance(target.get(key), dict):
                overlay(target[key], value, here)
                continue
            for path in [p for p in marks if p[: len(here)] == here]:
                del marks[path]
            target[key] = copy.deepcopy(value)
        for path, mark in child.marks.items():
            if path[: len(prefix)] == prefix and len(path) > len(prefix):
                marks.setdefault(path, mark)

    overlay(data, child.data, ())
    marks.update({path: mark for path, mark in child.marks.items() if not path})
    return LocatedDocument(data=data, file=child.file, marks=marks)


def _inheritance_key(reference: str, document: LocatedDocument) -> str:
    if reference.endswith(SPEC_SUFFIXES) or "/" in reference:
        base = document.data.get("__dir__")
        return str(Path(resolve_model_path(reference, Path(base) if base else None)))
    return reference


class _Resolver:
    """Resolves ``extends`` chains within a batch of documents and the registry, once each."""

    def __init__(self, batch: dict[str, LocatedDocument], lookup: ParentLookup) -> None:
        self.batch = batch  # by robot name
        self.lookup = lookup
        self.done: dict[int, LocatedDocument] = {}

    def resolve(self, document: LocatedDocument, chain: tuple[str, ...] = ()) -> LocatedDocument:
        if id(document) in self.done:
            return self.done[id(document)]
        reference = document.data.get("extends")
        if reference is None:
            return document
        where = document.marks.get(("extends", "<value>")) or document.location(("extends",))
        if not isinstance(reference, str) or not reference:
            raise SpecError(Problem("expected a robot name or a spec file path", where, "extends"))
        try:
            key = _inheritance_key(reference, document)
        except SpecError as error:  # a parent file outside the allowed folders
            raise SpecError([Problem(p.message, where, "extends") for p in error.problems]) from None
        own = str(document.data.get("name") or document.file)
        if key in chain or key == own:
            members = [*chain[chain.index(key) :], own] if key in chain else [own]
            start = members.index(min(members))  # one spelling per cycle, whichever file finds it
            members = members[start:] + members[:start]
            cycle = " -> ".join([*members, members[0]])
            raise SpecError(Problem(f"inheritance cycle: {cycle}; break it", where, "extends"))
        parent = self._find_parent(reference, key, where, document)
        merged = _merge(self.resolve(parent, (*chain, own)), document)
        self.done[id(document)] = merged
        return merged

    def _find_parent(
        self, reference: str, key: str, where: Location, child: LocatedDocument
    ) -> LocatedDocument:
        if key != reference:  # a file
            path = Path(key)
            if not path.is_file():
                raise SpecError(
                    Problem(f"parent spec file not found: {display_path(path)}", where, "extends")
                )
            return _read_document(path)
        if reference in self.batch:
            return self.batch[reference]
        found = self.lookup(reference)
        if found is None:
            from assembler.registry import registered_names

            own_name = child.data.get("name")  # may be anything, e.g. a list: compare, never hash
            known = sorted(name for name in {*self.batch, *registered_names()} if name != own_name)
            raise SpecError(
                Problem(
                    f"unknown spec '{reference}'.{did_you_mean(reference, known)} "
                    f"Known: {', '.join(known) or '(none)'}",
                    where,
                    "extends",
                )
            )
        return found


def _model_fields_at(model: type[BaseModel], path: DataPath) -> list[str]:
    """The keys a spec may use at ``path`` (following nested models, lists and mappings)."""
    current: Any = model
    for part in path:
        if isinstance(part, int) or not (isinstance(current, type) and issubclass(current, BaseModel)):
            current = _inner_model(current)
            if isinstance(part, int):
                continue
        if isinstance(current, type) and issubclass(current, BaseModel):
            field = current.model_fields.get(str(part))
            current = _inner_model(field.annotation) if field else None
    if isinstance(current, type) and issubclass(current, BaseModel):
        return list(current.model_fields)
    return []


def _inner_model(annotation: Any) -> Any:
    """The pydantic model inside ``X | None``, ``list[X]`` or ``dict[str, X]``, if there is one."""
    if isinstance(annotation, type) and issubclass(annotation, BaseModel):
        return annotation
    for argument in typing.get_args(annotation):
        found = _inner_model(argument)
        if found is not None:
            return found
    if isinstance(annotation, types.UnionType):
        return None
    return None


def _data_path(loc: tuple[Any, ...], data: Any) -> DataPath:
    """Pydantic's error location minus its internal parts (union branch tags), as a data path."""
    path: list[str | int] = []
    current = data
    for part in loc:
        if isinstance(current, dict) and isinstance(part, str):
            path.append(part)
            current = current.get(part)  # None below a missing or unknown key
        elif isinstance(current, list) and isinstance(part, int) and part < len(current):
            path.append(part)
            current = current[part]
        # anything else is pydantic's own (a union branch tag): not part of the user's data
    return tuple(path)


def problems_from_validation(
    error: ValidationError, document: LocatedDocument, model: type[BaseModel]
) -> list[Problem]:
    """One positioned problem per pydantic error, in reading order."""
    problems: list[Problem] = []
    short: dict[DataPath, int] = {}  # vectors given too few values: path -> values expected
    for item in error.errors():
        path = _data_path(tuple(item["loc"]), document.data)
        kind = item["type"]
        position = item["loc"][-1] if item["loc"] else None
        if kind == "missing" and isinstance(position, int):
            short[path] = max(short.get(path, 0), position + 1)
        elif kind == "missing":
            parent = path[:-1]
            message = f"missing required field '{path[-1]}'; add it"
            problems.append(Problem(message, document.location(parent), dotted(parent) or None))
        elif kind == "extra_forbidden":
            valid = sorted(_model_fields_at(model, path[:-1]))
            message = (
                f"unknown key '{path[-1]}'.{did_you_mean(str(path[-1]), valid)} "
                f"Valid keys here: {', '.join(valid)}"
            )
            problems.append(Problem(message, document.location(path), dotted(path)))
        else:
            where = document.marks.get((*path, "<value>")) or document.location(path)
            problems.append(Problem(item["msg"], where, dotted(path) or None))
    for path, expected in short.items():
        given = _value_at(document.data, path)
        count = len(given) if isinstance(given, list) else 0
        where = document.marks.get((*path, "<value>")) or document.location(path)
        problems.append(Problem(f"expected {expected} values, got {count}", where, dotted(path)))
    return sorted(problems, key=_reading_order)


def _reading_order(problem: Problem) -> tuple[str, int, int]:
    where = problem.location
    if where is None:
        return ("", 0, 0)
    return (where.file, where.line or 0, where.column or 0)


def _value_at(data: Any, path: DataPath) -> Any:
    for part in path:
        data = data[part]
    return data


def _spec_model(document: LocatedDocument) -> type[PartSpec]:
    return SPEC_KINDS.get(str(document.data.get("kind", "robot")), SPEC_KINDS["robot"])


def _validate(document: LocatedDocument) -> LoadedSpec:
    data = {k: v for k, v in document.data.items() if k != "__dir__"}
    kind = data.get("kind", "robot")
    if not isinstance(kind, str) or kind not in SPEC_KINDS:  # a list or a mapping is no kind
        raise SpecError(
            Problem(
                f"unknown spec kind '{kind}'; use one of {', '.join(SPEC_KINDS)}",
                document.marks.get(("kind", "<value>")) or document.location(("kind",)),
                "kind",
            )
        )
    try:
        spec = SPEC_KINDS[kind].model_validate(data)
    except ValidationError as error:
        raise SpecError(problems_from_validation(error, document, SPEC_KINDS[kind])) from None
    return LoadedSpec(spec=spec, document=document)


def _no_parent(name: str) -> LocatedDocument | None:
    return None


def spec_files(folder: Path) -> list[Path]:
    """Every spec file below ``folder``, in a stable order."""
    return sorted(p for p in folder.rglob("*") if p.suffix in SPEC_SUFFIXES and p.is_file())


def load_documents(
    documents: Iterable[LocatedDocument], lookup: ParentLookup = _no_parent
) -> list[LoadedSpec]:
    """Resolve inheritance and validate a batch of parsed documents; all problems in one error."""
    documents = list(documents)
    batch = {d.data["name"]: d for d in documents if isinstance(d.data.get("name"), str)}
    resolver = _Resolver(batch, lookup)
    loaded: list[LoadedSpec] = []
    problems: list[Problem] = []
    for document in documents:
        try:
            loaded.append(_validate(resolver.resolve(document)))
        except AssemblerError as error:
            seen = {p.message for p in problems}
            problems.extend(p for p in error.problems if p.message not in seen)
    if problems:
        raise SpecError(problems)
    return loaded


def load_paths(paths: Iterable[str | Path], lookup: ParentLookup = _no_parent) -> list[LoadedSpec]:
    """Load spec files and folders (recursively) together; every problem of every file at once."""
    documents: list[LocatedDocument] = []
    problems: list[Problem] = []
    for given in paths:
        path = Path(given)
        if path.is_dir():
            files = spec_files(path)
        elif path.exists():
            files = [path]
        else:
            problems.append(Problem(f"no such file or folder: {display_path(path)}"))
            continue
        for file in files:
            try:
                if file is not path:  # found in a folder: a link must not lead out of it
                    confine(file, [path], "spec file ")
                documents.append(_read_document(file))
            except AssemblerError as error:
                problems.extend(error.problems)
    try:
        loaded = load_documents(documents, lookup)
    except AssemblerError as error:
        problems.extend(error.problems)
        loaded = []
    if problems:
        raise SpecError(problems)
    return loaded


def load_string(text: str, lookup: ParentLookup = _no_parent, name: str = "<string>") -> LoadedSpec:
    """Load one spec from YAML text; relative paths in it are taken from the working directory."""
    document = parse_yaml(text, name)
    _resolve_paths(document, None)
    return load_documents([document], lookup)[0]
