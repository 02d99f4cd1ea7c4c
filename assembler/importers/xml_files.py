"""An MJCF file's XML as MuJoCo reads it, for ``assembler new``'s scene cut: the main file and the
files it includes, each element with its file and line (for the comment above a deletion), and
children listed with every ``<include>`` replaced by what the included file holds, where it stands."""

from __future__ import annotations

import xml.etree.ElementTree as ET
from collections.abc import Iterator
from dataclasses import dataclass, field
from pathlib import Path

from assembler.mjcf.xml_guard import original_lines


@dataclass
class XmlFiles:
    """The main file's and its included files' XML trees, with each element's file and line."""

    main: Path
    allowed: frozenset[Path]
    roots: dict[Path, ET.Element] = field(default_factory=dict)
    lines: dict[ET.Element, tuple[Path, int]] = field(default_factory=dict)

    def root(self, path: Path) -> ET.Element:
        if path not in self.roots:
            data = path.read_bytes()
            self.roots[path] = ET.fromstring(data)
            self.lines.update(
                (element, (path, line)) for element, line in original_lines(self.roots[path], data).items()
            )
        return self.roots[path]

    def children(self, parent: ET.Element) -> Iterator[ET.Element]:
        """``parent``'s children with each ``<include>`` replaced by the included file's children
        (MuJoCo resolves an include against the main file's folder)."""
        for child in parent:
            if child.tag != "include":
                yield child
                continue
            target = (self.main.parent / child.get("file", "")).resolve()
            if target in self.allowed:  # the files the reader checked and confined
                yield from self.children(self.root(target))

    def sections(self, tag: str) -> Iterator[ET.Element]:
        """Every top-level section ``<tag>`` of the model, wherever it is written."""
        yield from (child for child in self.children(self.root(self.main)) if child.tag == tag)

    def where(self, element: ET.Element) -> str:
        path, line = self.lines.get(element, (self.main, 0))
        return f"{path.name}:{line}" if line else path.name

    def every_root(self) -> list[ET.Element]:
        """The main file's tree and every included file's, as ``mjcf_fixes`` repairs them together."""
        pending = [self.root(self.main)]
        while pending:
            for include in list(pending.pop().iter("include")):
                target = (self.main.parent / include.get("file", "")).resolve()
                if target in self.allowed and target not in self.roots:
                    pending.append(self.root(target))
        return list(self.roots.values())
