"""Specs as they were at a git revision: ``specs/x.yaml@HEAD~1`` read with ``git show REV:path``.

A parent named by ``extends: <file>`` is read at the same revision when it is in the same
repository (a parent outside it, or ``extends: <name>``, comes from the working tree and the
registry as usual). The MJCF and meshes a spec points at are always read from the working tree:
a revision changes the spec's values, not the files it refers to.
"""

from __future__ import annotations

import subprocess
from pathlib import Path

from assembler.errors import Problem, SpecError
from assembler.files.paths import display_path, resolve_model_path
from assembler.registry.catalog import PARENTS
from assembler.spec.documents import (
    LoadedSpec,
    LocatedDocument,
    is_file_reference,
    parse_yaml,
    resolve_path_fields,
)
from assembler.spec.fieldpath import TOP
from assembler.spec.part_arguments import SPEC_SUFFIXES
from assembler.spec.schema import PartSpec
from assembler.spec.spec_files import load_documents


def split_revision(reference: str) -> tuple[Path, str] | None:
    """``specs/x.yaml@HEAD~1`` -> (path, revision); None when ``reference`` names no revision."""
    path, sep, revision = reference.rpartition("@")
    if not (sep and revision and path.endswith(SPEC_SUFFIXES)):
        return None
    if revision.startswith("-"):  # git would read it as an option (e.g. --output=FILE)
        raise SpecError(f"{reference}: '{revision}' is not a revision; name a commit, branch or tag")
    return Path(path), revision


def _git(folder: Path, *arguments: str) -> str:
    try:
        done = subprocess.run(["git", "-C", str(folder), *arguments], capture_output=True, text=True)
    except FileNotFoundError:
        raise SpecError(
            "git is not installed; it is needed to read a spec at a revision (FILE@REV)"
        ) from None
    if done.returncode != 0:
        lines = [line.removeprefix("fatal: ") for line in done.stderr.splitlines() if line.strip()]
        raise SpecError(lines[-1] if lines else f"git {' '.join(arguments)} failed")
    return done.stdout


def repository_of(path: Path) -> Path:
    """The top folder of the git repository holding ``path`` (which may not exist any more)."""
    folder = path.resolve().parent
    while not folder.is_dir():
        folder = folder.parent
    try:
        return Path(_git(folder, "rev-parse", "--show-toplevel").strip()).resolve()
    except SpecError:
        raise SpecError(
            f"{display_path(path)}: not inside a git repository, so no revision of it exists"
        ) from None


def text_at(path: Path, revision: str, repository: Path | None = None) -> str:
    """The text of ``path`` (any file of a git repository, found when not given) at ``revision``; one
    line if git cannot."""
    repository = repository or repository_of(path)
    relative = path.resolve().relative_to(repository).as_posix()
    try:
        return _git(repository, "show", f"{revision}:{relative}")
    except SpecError as error:
        shown = f"{display_path(path)}@{revision}"
        raise SpecError(
            Problem(f"cannot read it from git: {error.problems[0].message}", None, shown)
        ) from None


def _document_at(path: Path, revision: str, repository: Path) -> LocatedDocument:
    text = text_at(path, revision, repository)
    document = parse_yaml(text, f"{display_path(path)}@{revision}", path.resolve().parent)
    resolve_path_fields(document)  # relative to the file's folder, as for files on disk
    return document


def load_at_revision(path: Path, revision: str) -> LoadedSpec[PartSpec]:
    """The spec ``path`` held at ``revision``, its same-repository ``extends:`` files read there too.

    Parents read at the revision join the batch under their names, and the child's ``extends`` is
    pointed at that name, so the loader's usual inheritance applies; the spec keeps the
    ``extends`` value its file wrote.
    """
    repository = repository_of(path)
    child = _document_at(path, revision, repository)
    written = child.data.get("extends")
    documents, current, current_path, seen = [child], child, path.resolve(), {path.resolve()}
    while is_file_reference(reference := current.data.get("extends")):
        parent_path = Path(resolve_model_path(str(reference), current_path.parent))
        if parent_path in seen or not parent_path.is_relative_to(repository):
            break  # a cycle (the loader reports it) or a file outside the repository (read from disk)
        parent = _document_at(parent_path, revision, repository)
        if not isinstance(parent.data.get("name"), str):
            raise SpecError(Problem("missing required field 'name'; add it", parent.field_location(TOP)))
        current.data["extends"] = parent.data["name"]
        documents.append(parent)
        current, current_path = parent, parent_path
        seen.add(parent_path)
    loaded = load_documents(documents, PARENTS)[0]
    spec = loaded.spec.model_copy(update={"extends": written})
    return LoadedSpec(spec=spec, document=loaded.document)
