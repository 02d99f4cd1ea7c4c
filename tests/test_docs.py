"""The documentation holds: the generated pages (API and command-line references) are what their
generator writes now, every public name is declared once and documented, and every relative link of
the README and of docs/ leads somewhere."""

from __future__ import annotations

import importlib.util
import inspect
import re
import subprocess
import sys
from pathlib import Path
from types import ModuleType

import pytest

import assembler
from tests.facades import type_checking_imports

ROOT = Path(__file__).parent.parent
README = ROOT / "README.md"
PAGES = sorted((ROOT / "docs").glob("*.md"))
LINKED = [README, *PAGES]


# ----- the API, declared once -------------------------------------------------------------------------


def test_all_is_the_api_table_each_name_once() -> None:
    declared = [name for names in assembler.API.values() for name in names]
    assert assembler.__all__ == declared
    assert len(set(declared)) == len(declared)


def test_what_type_checkers_read_is_the_api_table() -> None:
    imports = type_checking_imports(ROOT / "assembler" / "__init__.py")
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


# ----- links --------------------------------------------------------------------------------------------

FENCED = re.compile(r"^```.*?^```", flags=re.DOTALL | re.MULTILINE)
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")


def _prose(page: Path) -> str:
    """A page without its code blocks and inline code, where brackets are no links."""
    return re.sub(r"`[^`\n]*`", "", FENCED.sub("", page.read_text()))


def _anchors(page: Path) -> set[str]:
    """The anchors GitHub makes of a page's headings: lower case, punctuation dropped, spaces to
    hyphens, a repeated one numbered."""
    anchors: set[str] = set()
    for heading in re.findall(r"^#{1,6} +(.+?) *#*$", FENCED.sub("", page.read_text()), flags=re.MULTILINE):
        slug = re.sub(r"[^\w\- ]", "", heading.lower()).replace(" ", "-")
        anchor, n = slug, 0
        while anchor in anchors:
            n += 1
            anchor = f"{slug}-{n}"
        anchors.add(anchor)
    return anchors


def _relative_links(page: Path) -> list[str]:
    return [target for target in LINK.findall(_prose(page)) if not re.match(r"[a-z]+:", target)]


@pytest.mark.parametrize("page", LINKED, ids=lambda p: str(p.relative_to(ROOT)))
def test_every_relative_link_leads_to_a_file_and_heading(page: Path) -> None:
    broken = []
    for target in _relative_links(page):
        path, _, anchor = target.partition("#")
        linked = (page.parent / path).resolve() if path else page
        if not linked.exists():
            broken.append(f"{target}: no file {linked.relative_to(ROOT.resolve())}")
        elif anchor and linked.suffix == ".md" and anchor not in _anchors(linked):
            broken.append(f"{target}: no heading '{anchor}' in {linked.name}")
    assert broken == []


def test_anchors_are_made_as_github_makes_them() -> None:
    anchors = _anchors(ROOT / "docs" / "getting-started.md")
    assert {"what-already-set-means", "spec-repositories", "robosuites-robots"} <= anchors
    assert "the-robosuite-block" in _anchors(ROOT / "docs" / "robosuite.md")


def test_the_index_leads_to_every_page() -> None:
    linked = {target.partition("#")[0] for target in _relative_links(ROOT / "docs" / "index.md")}
    assert sorted(page.name for page in PAGES if page.name != "index.md") == sorted(linked - {"../README.md"})


def test_the_readme_leads_to_the_index_and_stays_short() -> None:
    assert "docs/index.md" in _relative_links(README)
    assert len(README.read_text().splitlines()) <= 200
