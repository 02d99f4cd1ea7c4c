"""The documentation holds: the generated pages (API and command-line references) are what their
generator writes now, and every public name is declared once and documented."""

from __future__ import annotations

import ast
import importlib.util
import inspect
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

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


def _generator() -> ModuleType:
    """``docs/generate.py``, which writes docs/api.md and docs/cli.md (it is no package module)."""
    spec = importlib.util.spec_from_file_location("docs_generate", ROOT / "docs" / "generate.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


GENERATE = _generator()


# ----- the generated pages ----------------------------------------------------------------------------


@pytest.mark.parametrize("page", sorted(GENERATE.PAGES))
def test_committed_generated_page_is_what_the_generator_writes_now(page: str) -> None:
    committed = (ROOT / page).read_text()
    assert committed == GENERATE.PAGES[page](), f"{page} is stale; regenerate it: {GENERATE.REGENERATE}"


def test_every_public_name_has_a_docstring() -> None:
    undocumented = [
        name
        for module, names in assembler.API.items()
        for name in names
        if not (GENERATE.documented(module, name)[1] or "").strip()
    ]
    assert undocumented == []


def test_every_public_name_has_a_row_in_the_api_reference() -> None:
    reference = (ROOT / GENERATE.API_PAGE).read_text()
    rows = re.findall(r"^\| `(\w+)", reference, flags=re.MULTILINE)
    assert rows == assembler.__all__


def test_the_api_reference_says_a_values_own_docstring() -> None:
    reference = (ROOT / GENERATE.API_PAGE).read_text()
    assert (
        "| `REGISTERED_ROBOTS` | value: `Registry` | Every registered robot class by name, in registration order. |"
        in reference
    )
    assert (
        "| `RobotModelMeta` | metaclass | robosuite's name for the metaclass of robot classes. |" in reference
    )
    assert (
        "| `SpecError` | exception | A spec file (YAML) is malformed, invalid, or inconsistent with its MJCF. |"
        in reference
    )


def test_every_command_and_flag_is_in_the_command_line_reference() -> None:
    from assembler.cli.arguments import COMMANDS, build_parser

    reference = (ROOT / GENERATE.CLI_PAGE).read_text()
    parser = build_parser()
    (commands,) = [a for a in parser._actions if a.dest == "command"]
    assert [c.name for c in COMMANDS] == list(commands.choices)  # type: ignore[attr-defined]
    for name, subparser in commands.choices.items():  # type: ignore[attr-defined]
        section = reference.split(f"\n## assembler {name}\n", 1)[1].split("\n## ", 1)[0]
        for action in subparser._actions:
            for flag in action.option_strings:
                if flag not in ("-h", "--help", "--specs", "--allow-path"):
                    assert f"`{flag}" in section or f", {flag}" in section, f"{name} {flag}"
    for flag in ("--specs DIR", "--allow-path DIR"):
        assert f"| `{flag}` |" in reference
