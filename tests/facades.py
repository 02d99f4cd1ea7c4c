"""What type checkers read of a package that gives its names on first use (``assembler``,
``assembler.models``): the imports under its ``if TYPE_CHECKING:``."""

from __future__ import annotations

import ast
from pathlib import Path


def type_checking_imports(init: Path) -> list[tuple[str, str, str | None]]:
    """(module, name, alias) of each import under ``if TYPE_CHECKING:`` in the ``__init__.py`` at
    ``init``."""
    tree = ast.parse(init.read_text())
    (block,) = [
        node
        for node in tree.body
        if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING"
    ]
    imports = []
    for node in block.body:
        assert isinstance(node, ast.ImportFrom) and node.module, ast.unparse(node)
        imports += [(node.module, alias.name, alias.asname) for alias in node.names]
    return imports
