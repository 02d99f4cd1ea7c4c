"""The public API is declared once: ``__all__`` is :data:`assembler.API`, the imports type checkers
read say the same, every name is what its module gives, and ``import assembler`` stays light."""

from __future__ import annotations

import ast
import importlib
import inspect
import subprocess
import sys
from pathlib import Path

import assembler

ROOT = Path(__file__).parent.parent


# ----- the API, declared once -------------------------------------------------------------------------


def _type_checking_imports() -> list[tuple[str, str, str | None]]:
    """(module, name, alias) of each import under ``if TYPE_CHECKING:`` in ``assembler/__init__.py``."""
    tree = ast.parse((ROOT / "assembler" / "__init__.py").read_text())
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


def test_all_is_the_api_table_each_name_once() -> None:
    declared = [name for names in assembler.API.values() for name in names]
    assert assembler.__all__ == declared
    assert len(set(declared)) == len(declared)


def test_what_type_checkers_read_is_the_api_table() -> None:
    imports = _type_checking_imports()
    assert [(module, name) for module, name, _ in imports if _ != name] == []  # each `X as X`: re-exported
    assert sorted((module, name) for module, name, _ in imports) == sorted(
        (module, name) for module, names in assembler.API.items() for name in names
    )


def test_every_public_name_is_what_its_declared_module_gives() -> None:
    for module, names in assembler.API.items():
        for name in names:
            value = getattr(assembler, name)
            if name in assembler.ANSWERED_FROM_THE_CACHE:
                declared = getattr(importlib.import_module(module), name)
                assert (
                    inspect.signature(value).parameters.keys()
                    == inspect.signature(declared).parameters.keys()
                )
            else:
                assert value is getattr(importlib.import_module(module), name), name


def test_import_assembler_loads_neither_mujoco_nor_pydantic() -> None:
    code = "import sys, assembler; print([m for m in ('mujoco', 'pydantic', 'numpy') if m in sys.modules])"
    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert run.stdout.strip() == "[]"
