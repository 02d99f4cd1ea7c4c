"""YAML text -> plain data plus the file:line:column of every value, refusing what PyYAML lets by.

PyYAML's safe loader silently keeps the last of two equal keys and forgets where values came
from. Specs are reviewed by people, so we compose the node graph ourselves: duplicate keys are
errors, keys must be strings, and every mapping key and value remembers its position so that a
schema error can point at the line a reviewer must change.

Specs may also come from strangers, so reading is bounded (:mod:`assembler.files.limits`): file size,
nesting depth, items per list, and the number of values aliases may expand to.
"""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path
from typing import Any

import yaml

from assembler.errors import Location, Problem, SpecError
from assembler.files.inputs import note_inputs
from assembler.files.limits import MAX_SPEC_BYTES, MAX_YAML_DEPTH, MAX_YAML_ITEMS, MAX_YAML_VALUES
from assembler.files.regular import FileTooLarge, read_bounded
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.fieldpath import TOP, FieldPath

PLAIN_DATA_TAGS = frozenset(
    f"tag:yaml.org,2002:{name}" for name in ("map", "seq", "str", "int", "float", "bool", "null")
)
"""The only node types a spec may contain: no Python objects, no timestamps, no binary."""


def _location(file: str, node: yaml.Node) -> Location:
    return Location(file, node.start_mark.line + 1, node.start_mark.column + 1)


class _DepthLimitedLoader(yaml.SafeLoader):  # type: ignore[misc]  # PyYAML has no type stubs here
    """PyYAML's safe composer with a bound on nesting (it recurses once per level)."""

    def __init__(self, text: str, file: str) -> None:
        super().__init__(text)
        self.file = file
        self.depth = 0

    def compose_node(self, parent: yaml.Node | None, index: Any) -> yaml.Node | None:
        self.depth += 1
        try:
            if self.depth > MAX_YAML_DEPTH:
                mark = self.peek_event().start_mark
                raise SpecError(
                    Problem(
                        f"nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels; "
                        "a spec nests a few levels deep",
                        Location(self.file, mark.line + 1, mark.column + 1),
                    )
                )
            return super().compose_node(parent, index)
        finally:
            self.depth -= 1


_NOT_TEXT = yaml.reader.Reader.NON_PRINTABLE
"""Characters YAML refuses in its text (control characters but tab and line ends, surrogates...)."""


class _Builder:
    """Turns composed YAML nodes into Python data, collecting positions and problems.

    Aliases are expanded here (a node may be reached many times), so the values built are
    counted and building stops at :data:`MAX_YAML_VALUES`.
    """

    def __init__(self, file: str) -> None:
        self.file = file
        self.fields: dict[FieldPath, Location] = {}
        self.values: dict[FieldPath, Location] = {}
        self.problems: list[Problem] = []
        self.built = 0
        self._open: set[int] = set()  # collections being built: an alias back to one is a cycle
        self._constructor = yaml.constructor.SafeConstructor()

    def build(self, node: yaml.Node, path: FieldPath) -> Any:
        if id(node) in self._open:
            raise SpecError(
                Problem(
                    "a recursive alias (an anchor used inside itself) has no value; write the values out",
                    _location(self.file, node),
                    path or None,
                )
            )
        if len(path) > MAX_YAML_DEPTH:  # aliases can nest deeper than the text does
            raise SpecError(
                Problem(
                    f"nesting depth exceeds the limit of {MAX_YAML_DEPTH} levels once aliases are expanded",
                    _location(self.file, node),
                    path or None,
                )
            )
        self.built += 1
        if self.built > MAX_YAML_VALUES:
            raise SpecError(
                Problem(
                    f"the values in the document, aliases expanded, exceed the limit of {MAX_YAML_VALUES}; "
                    "each alias (*name) repeats all its anchor names: write the values out instead",
                    _location(self.file, node),
                    path or None,
                )
            )
        self.fields.setdefault(path, _location(self.file, node))
        if node.tag not in PLAIN_DATA_TAGS:
            self._problem(node, path, f"YAML tag '{node.tag}' is not allowed; specs are plain data")
            return None
        if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)) and len(node.value) > MAX_YAML_ITEMS:
            kind = "mapping" if isinstance(node, yaml.MappingNode) else "list"
            raise SpecError(
                Problem(
                    f"a {kind} of {len(node.value)} items exceeds the limit of {MAX_YAML_ITEMS} items",
                    _location(self.file, node),
                    path or None,
                )
            )
        if isinstance(node, (yaml.MappingNode, yaml.SequenceNode)):
            self._open.add(id(node))
            try:
                if isinstance(node, yaml.MappingNode):
                    return self._mapping(node, path)
                return [self.build(item, path.child(index)) for index, item in enumerate(node.value)]
            finally:
                self._open.discard(id(node))
        return self._scalar(node, path)

    def _scalar(self, node: yaml.Node, path: FieldPath) -> Any:
        try:
            value = self._constructor.construct_object(node, deep=True)
        except (ValueError, KeyError, TypeError, OverflowError):
            # e.g. "!!float abc", "!!bool maybe", or an integer of 5000 digits
            kind = node.tag.rsplit(":", 1)[-1]
            self._problem(node, path, f"YAML: cannot read {_short(node.value)!r} as {kind}")
            return None
        control = _NOT_TEXT.search(value) if isinstance(value, str) else None
        if control is not None:  # "\x07", "\0": what YAML refuses written out, it lets in as an escape
            self._problem(
                node,
                path,
                f"YAML: character #x{ord(control.group()):04x} (written as an escape) is not allowed in "
                "text; remove it",
            )
            return None
        return value

    def _mapping(self, node: yaml.MappingNode, path: FieldPath) -> dict[str, Any]:
        result: dict[str, Any] = {}
        first_seen: dict[str, Location] = {}
        for key_node, value_node in node.value:
            if key_node.tag == "tag:yaml.org,2002:merge":
                self._problem(key_node, path, "YAML merge keys ('<<') are not supported; write the keys out")
                continue
            # Built like any value (tags checked, counted), at a placeholder path that is then dropped.
            key_placeholder = path.child("<key>")
            before = len(self.problems)
            key = self.build(key_node, key_placeholder) if isinstance(key_node, yaml.ScalarNode) else None
            self.fields.pop(key_placeholder, None)
            if len(self.problems) > before:  # the key's own problem (a control character), said once
                self.problems[before:] = [replace(p, path=path or None) for p in self.problems[before:]]
                continue
            if not isinstance(key, str):
                self._problem(key_node, path, f"keys must be text, got {key_node.tag.rsplit(':', 1)[-1]}")
                continue
            here = _location(self.file, key_node)
            if key in first_seen:
                self._problem(
                    key_node,
                    path.child(key),
                    f"duplicate key '{key}' (first at line {first_seen[key].line}); keep one",
                )
                continue
            first_seen[key] = here
            # A key's own position is what an "unknown key" error should point at.
            key_path = path.child(key)
            self.fields[key_path] = here
            result[key] = self.build(value_node, key_path)
            if not isinstance(value_node, yaml.ScalarNode) or value_node.value:
                self.values[key_path] = _location(self.file, value_node)
        return result

    def _problem(self, node: yaml.Node, path: FieldPath, message: str) -> None:
        self.problems.append(Problem(message, _location(self.file, node), path or None))


def _short(text: object, limit: int = 40) -> str:
    """A value as it may be quoted in a message: one line, cut to ``limit`` characters."""
    shown = " ".join(str(text).split())
    return shown if len(shown) <= limit else shown[: limit - 3] + "..."


def read_yaml_text(path: Path, shown: str) -> str:
    """A YAML file's text: at most :data:`MAX_SPEC_BYTES` read, UTF-8 with or without a BOM; the file
    is noted as an input, which no output of this process may replace (:mod:`assembler.files.inputs`)."""
    try:
        raw = read_bounded(path, MAX_SPEC_BYTES)  # a FIFO or a device is refused, never waited on
    except FileTooLarge as error:
        raise SpecError(Problem(f"{error.strerror} for a spec file", Location(shown))) from None
    except OSError as error:
        raise SpecError(Problem(f"cannot read the file: {error.strerror}", Location(shown))) from None
    note_inputs([path])
    try:
        return raw.decode("utf-8-sig")  # a byte-order mark is harmless; strip it
    except UnicodeDecodeError as error:
        raise SpecError(
            Problem(f"the file is not UTF-8 text (byte {error.start}); save it as UTF-8", Location(shown))
        ) from None


_FAST_LOADER: Any = getattr(yaml, "CSafeLoader", None)
"""libyaml's composer (when PyYAML was built with it): several times faster than the pure-Python one."""

_OPENING = (yaml.MappingStartEvent, yaml.SequenceStartEvent)
_CLOSING = (yaml.MappingEndEvent, yaml.SequenceEndEvent)


def _fast_compose(text: str) -> yaml.Node | None:
    """The node graph composed by libyaml, after a flat scan of its events checked the nesting depth
    (libyaml's composer recurses in C, where no depth limit would stop it)."""
    depth = 0
    for event in yaml.parse(text, Loader=_FAST_LOADER):
        if isinstance(event, _OPENING):
            depth += 1
            if depth > MAX_YAML_DEPTH:
                raise yaml.YAMLError("too deep")
        elif isinstance(event, _CLOSING):
            depth -= 1
    return yaml.compose(text, Loader=_FAST_LOADER)


def _compose(text: str, file: str) -> yaml.Node | None:
    """The document's node graph (aliases not yet expanded), or a positioned :class:`SpecError`."""
    if _FAST_LOADER is not None:
        try:
            return _fast_compose(text)
        except yaml.YAMLError:
            pass  # composed again below, where the error gets its exact words and position
    loader: _DepthLimitedLoader | None = None
    try:
        loader = _DepthLimitedLoader(text, file)  # its reader checks the characters at once
        return loader.get_single_node()
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        where = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        reason = error.problem or error.context or "invalid YAML"
        if reason.startswith("but ") and error.context:  # "expected a single document ... but found"
            reason = f"{error.context} {reason}"
        reason = _short(reason, 200)
        raise SpecError(Problem(f"YAML syntax error: {reason}", where)) from None
    except yaml.reader.ReaderError as error:
        # a control character: name it and its position, not PyYAML's multi-line text
        line = text.count("\n", 0, error.position) + 1
        column = error.position - (text.rfind("\n", 0, error.position) + 1) + 1
        character = error.character if isinstance(error.character, str) else chr(error.character)
        raise SpecError(
            Problem(
                f"YAML: character #x{ord(character):04x} is not allowed in YAML text",
                Location(file, line, column),
            )
        ) from None
    except yaml.YAMLError as error:
        raise SpecError(Problem(f"YAML error: {_short(error, 200)}", Location(file))) from None
    finally:
        if loader is not None:
            loader.dispose()


def parse_yaml_value(text: str, where: str) -> Any:
    """One YAML value written outside a file (the ``VALUE`` of ``--set PATH=VALUE``), read with a spec
    file's bounds and rules (nesting depth, items, aliases expanded, plain tags, no control
    characters); a problem is a :class:`SpecError` naming ``where`` (``--set init_qpos``)."""
    problems: list[Problem]
    try:
        node = _compose(text, where)
        if node is None:
            return None
        builder = _Builder(where)
        value = builder.build(node, TOP)
        problems = builder.problems
    except SpecError as error:
        problems = list(error.problems)
    except yaml.constructor.ConstructorError as error:
        problems = [Problem(f"YAML: {_short(error.problem, 200)}")]
    if problems:
        raise SpecError([Problem(problem.message, None, where) for problem in problems])
    return value


def parse_yaml(text: str, file: str, folder: Path | None = None) -> LocatedDocument:
    """Parse one YAML document that must be a mapping; raise :class:`SpecError` with positions.
    ``folder`` is where the document's relative file references start (None: the working directory)."""
    if len(text) > MAX_SPEC_BYTES:
        raise SpecError(
            Problem(
                f"the text's length exceeds the limit of {MAX_SPEC_BYTES} characters for a spec",
                Location(file),
            )
        )
    node = _compose(text, file)
    if node is None:
        raise SpecError(Problem("the file is empty; a spec is a YAML mapping", Location(file, 1, 1)))
    if not isinstance(node, yaml.MappingNode):
        raise SpecError(Problem("a spec must be a YAML mapping (key: value lines)", _location(file, node)))
    builder = _Builder(file)
    try:
        data = builder.build(node, TOP)
    except yaml.constructor.ConstructorError as error:
        mark = error.problem_mark
        where = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        raise SpecError(Problem(f"YAML: {_short(error.problem, 200)}", where)) from None
    if builder.problems:
        raise SpecError(builder.problems)
    return LocatedDocument(data=data, file=file, folder=folder, fields=builder.fields, values=builder.values)
