"""YAML text -> plain data plus the file:line:column of every value, refusing what PyYAML lets by.

PyYAML's safe loader silently keeps the last of two equal keys and forgets where values came
from. Specs are reviewed by people, so we compose the node graph ourselves: duplicate keys are
errors, keys must be strings, and every mapping key and value remembers its position so that a
schema error can point at the line a reviewer must change.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import yaml

from assembler.errors import Location, Problem, SpecError

PLAIN_DATA_TAGS = frozenset(
    f"tag:yaml.org,2002:{name}" for name in ("map", "seq", "str", "int", "float", "bool", "null")
)
"""The only node types a spec may contain: no Python objects, no timestamps, no binary."""

DataPath = tuple[str | int, ...]
"""Where a value sits in a document: mapping keys and list indices from the top."""


@dataclass
class LocatedDocument:
    """A parsed YAML mapping and the position of each of its values (and of each key)."""

    data: dict[str, Any]
    file: str
    marks: dict[DataPath, Location] = field(default_factory=dict)

    def location(self, path: DataPath) -> Location:
        """The position of the deepest part of ``path`` that has one (the document start at worst)."""
        for end in range(len(path), -1, -1):
            mark = self.marks.get(tuple(path[:end]))
            if mark is not None:
                return mark
        return Location(self.file, 1, 1)


def dotted(path: DataPath) -> str:
    """``joints[1].match`` for ``("joints", 1, "match")``: how users write a path."""
    text = ""
    for part in path:
        text += f"[{part}]" if isinstance(part, int) else (f".{part}" if text else str(part))
    return text


def _location(file: str, node: yaml.Node) -> Location:
    return Location(file, node.start_mark.line + 1, node.start_mark.column + 1)


class _Builder:
    """Turns composed YAML nodes into Python data, collecting marks and problems."""

    def __init__(self, file: str) -> None:
        self.file = file
        self.marks: dict[DataPath, Location] = {}
        self.problems: list[Problem] = []
        self._constructor = yaml.constructor.SafeConstructor()

    def build(self, node: yaml.Node, path: DataPath) -> Any:
        self.marks.setdefault(path, _location(self.file, node))
        if node.tag not in PLAIN_DATA_TAGS:
            self._problem(node, path, f"YAML tag '{node.tag}' is not allowed; specs are plain data")
            return None
        if isinstance(node, yaml.MappingNode):
            return self._mapping(node, path)
        if isinstance(node, yaml.SequenceNode):
            return [self.build(item, (*path, index)) for index, item in enumerate(node.value)]
        return self._constructor.construct_object(node, deep=True)

    def _mapping(self, node: yaml.MappingNode, path: DataPath) -> dict[str, Any]:
        result: dict[str, Any] = {}
        first_seen: dict[str, Location] = {}
        for key_node, value_node in node.value:
            if key_node.tag == "tag:yaml.org,2002:merge":
                self._problem(key_node, path, "YAML merge keys ('<<') are not supported; write the keys out")
                continue
            key = self.build(key_node, (*path, "<key>")) if isinstance(key_node, yaml.ScalarNode) else None
            if not isinstance(key, str):
                self._problem(key_node, path, f"keys must be text, got {key_node.tag.rsplit(':', 1)[-1]}")
                continue
            here = _location(self.file, key_node)
            if key in first_seen:
                self._problem(
                    key_node,
                    (*path, key),
                    f"duplicate key '{key}' (first at line {first_seen[key].line}); keep one",
                )
                continue
            first_seen[key] = here
            # A key's own position is what an "unknown key" error should point at.
            key_path: DataPath = (*path, key)
            self.marks[key_path] = here
            result[key] = self.build(value_node, key_path)
            if not isinstance(value_node, yaml.ScalarNode) or value_node.value:
                self.marks[key_path + ("<value>",)] = _location(self.file, value_node)
        self.marks.pop((*path, "<key>"), None)
        return result

    def _problem(self, node: yaml.Node, path: DataPath, message: str) -> None:
        self.problems.append(Problem(message, _location(self.file, node), dotted(path) or None))


def parse_yaml(text: str, file: str) -> LocatedDocument:
    """Parse one YAML document that must be a mapping; raise :class:`SpecError` with positions."""
    try:
        node = yaml.compose(text, Loader=yaml.SafeLoader)
    except yaml.MarkedYAMLError as error:
        mark = error.problem_mark or error.context_mark
        where = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        reason = error.problem or error.context or "invalid YAML"
        raise SpecError(Problem(f"YAML syntax error: {reason}", where)) from None
    except yaml.YAMLError as error:
        raise SpecError(Problem(f"YAML error: {error}", Location(file))) from None
    if node is None:
        raise SpecError(Problem("the file is empty; a spec is a YAML mapping", Location(file, 1, 1)))
    if not isinstance(node, yaml.MappingNode):
        raise SpecError(Problem("a spec must be a YAML mapping (key: value lines)", _location(file, node)))
    builder = _Builder(file)
    try:
        data = builder.build(node, ())
    except yaml.constructor.ConstructorError as error:
        mark = error.problem_mark
        where = Location(file, mark.line + 1, mark.column + 1) if mark else Location(file)
        raise SpecError(Problem(f"YAML: {error.problem}", where)) from None
    if builder.problems:
        raise SpecError(builder.problems)
    return LocatedDocument(data=data, file=file, marks=builder.marks)
