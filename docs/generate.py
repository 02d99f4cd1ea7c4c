"""Writes the two generated pages of the documentation: the API reference (``docs/api.md``, from
:data:`assembler.API`, the one declaration of the public API) and the command-line reference
(``docs/cli.md``, from the parser ``assembler --help`` prints). ``tests/test_docs.py`` fails when a
committed page differs from what this writes now.

    python docs/generate.py          # rewrite both pages
"""

from __future__ import annotations

import argparse
import ast
import importlib
import importlib.util
import inspect
import re
import sys
from pathlib import Path
from typing import Any

import assembler
from assembler.cli.arguments import COMMANDS, build_parser

ROOT = Path(__file__).resolve().parent.parent
API_PAGE = "docs/api.md"
CLI_PAGE = "docs/cli.md"
REGENERATE = "python docs/generate.py"

# ----- the API reference ----------------------------------------------------------------------------


def _module_tree(module: str) -> ast.Module:
    spec = importlib.util.find_spec(module)
    assert spec is not None and spec.origin is not None, module
    return ast.parse(Path(spec.origin).read_text())


def _assigned_names(node: ast.stmt) -> list[str]:
    if isinstance(node, ast.Assign):
        return [target.id for target in node.targets if isinstance(target, ast.Name)]
    if isinstance(node, ast.AnnAssign) and isinstance(node.target, ast.Name):
        return [node.target.id]
    return []


def value_docstring(module: str, name: str) -> str | None:
    """The docstring written under ``name = ...`` in ``module``, following ``from X import name``
    to the module that assigns it. A module that assigns nothing else (``version.py``) documents
    its one value with its own docstring."""
    tree = _module_tree(module)
    for node, after in zip(tree.body, [*tree.body[1:], None], strict=True):
        if name in _assigned_names(node):
            if (
                isinstance(after, ast.Expr)
                and isinstance(after.value, ast.Constant)
                and isinstance(after.value.value, str)
            ):
                return inspect.cleandoc(after.value.value)
            assigned = {n for statement in tree.body for n in _assigned_names(statement)}
            return ast.get_docstring(tree) if assigned == {name} else None
        for imported in _imports_of(node):
            for alias in imported.names:
                if (alias.asname or alias.name) == name:
                    return value_docstring(str(imported.module), alias.name)
    return None


def _imports_of(node: ast.stmt) -> list[ast.ImportFrom]:
    """The absolute ``from X import`` statements ``node`` is, or (an ``if TYPE_CHECKING:`` block of a
    package that gives its names on first use, ``assembler.models``) holds."""
    if isinstance(node, ast.If) and isinstance(node.test, ast.Name) and node.test.id == "TYPE_CHECKING":
        return [n for n in node.body if isinstance(n, ast.ImportFrom) and n.module and n.level == 0]
    return [node] if isinstance(node, ast.ImportFrom) and node.module and node.level == 0 else []


def documented(module: str, name: str) -> tuple[str, str | None]:
    """What the reference says of ``name`` taken from ``module``: its kind and its docstring."""
    value = getattr(importlib.import_module(module), name)
    own = value_docstring(module, name)  # an alias (RobotModelMeta) is documented where it is made
    if inspect.isclass(value):
        kind = "exception" if issubclass(value, BaseException) else "class"
        kind = "metaclass" if issubclass(value, type) else kind
        return kind, own or inspect.getdoc(value)
    if callable(value):
        return "function", own or inspect.getdoc(value)
    return f"value: `{type(value).__name__}`", own


STARS = {inspect.Parameter.VAR_POSITIONAL: "*", inspect.Parameter.VAR_KEYWORD: "**"}


def _call(value: Any) -> str:
    """A function's parameters by name (``*args``, ``**kwargs`` marked), without types or defaults."""
    parameters = inspect.signature(value).parameters.values()
    return "(" + ", ".join(STARS.get(p.kind, "") + p.name for p in parameters) + ")"


def summary(docstring: str) -> str:
    """A docstring's first paragraph on one line, its reStructuredText roles and literals as Markdown."""
    text = " ".join(docstring.strip().split("\n\n")[0].split())
    text = re.sub(r":\w+:`~[\w.]*?(\w+)`", r"`\1`", text)  # :func:`~a.b.c` -> `c`
    text = re.sub(r":\w+:`([^`]+)`", r"`\1`", text)  # :mod:`a.b` -> `a.b`
    return text.replace("``", "`").replace("|", "\\|")


def api_markdown() -> str:
    """The API reference: every name in ``assembler.__all__``, one row each, in :data:`assembler.API`'s
    order (a robot first, errors last)."""
    lines = [
        "# API reference",
        "",
        f"<!-- Generated from `assembler.API` by `{REGENERATE}`; tests/test_docs.py keeps it current. -->",
        "",
        "Every public name of `import assembler`, imported on first use (`import assembler` itself",
        "loads neither MuJoCo nor pydantic), with the first paragraph of its docstring;",
        "`help(assembler.NAME)` says the rest. Worked examples: [getting started](getting-started.md).",
        "",
        "| name | kind | what it is |",
        "|---|---|---|",
    ]
    for module, names in assembler.API.items():
        for name in names:
            kind, doc = documented(module, name)
            value = getattr(importlib.import_module(module), name)
            call = _call(value) if kind == "function" else ""
            lines.append(f"| `{name}{call}` | {kind} | {summary(doc or '')} |")
    return "\n".join(lines) + "\n"


# ----- the command-line reference -------------------------------------------------------------------


def _choices(action: argparse.Action) -> str:
    return "{" + ",".join(map(str, action.choices or ())) + "}"


def _flag(action: argparse.Action) -> str:
    """An argument as ``--help`` writes it: ``ROBOT``, ``[PATHS ...]``, ``-o, --output OUTPUT``."""
    if not action.option_strings:
        name = action.metavar or (_choices(action) if action.choices else action.dest.upper())
        return {"?": f"[{name}]", "*": f"[{name} ...]"}.get(str(action.nargs), str(name))
    if action.nargs == 0:
        return ", ".join(action.option_strings)
    value = action.metavar or (_choices(action) if action.choices else action.dest.upper())
    return ", ".join(action.option_strings) + (f" [{value}]" if action.nargs == "?" else f" {value}")


def _text(text: str) -> str:
    """Help text as a Markdown table cell: one line, ``<`` and ``|`` escaped."""
    return " ".join(text.split()).replace("<", "&lt;").replace("|", "\\|")


def _rows(parser: argparse.ArgumentParser, leave_out: set[str]) -> list[str]:
    return [
        f"| `{_flag(action)}` | {_text(action.help or '')} |"
        for action in parser._actions
        if not isinstance(action, argparse._HelpAction) and action.dest not in leave_out
    ]


CLI_INTRODUCTION = """\
`assembler [--specs DIR] [--allow-path DIR] COMMAND ...`: every command's arguments and flags, as
`assembler COMMAND --help` prints them. Worked examples: [getting started](getting-started.md).

Exit codes: 0 success; 1 a problem in the user's input (one line per problem on standard error, no
traceback); 2 a usage error (argparse's); 130 interrupted; 141 standard output closed early
(`assembler list | head -1`). The cache's environment variables (`ASSEMBLER_CACHE_DIR`,
`ASSEMBLER_NO_CACHE`, `ASSEMBLER_CACHE_MAX_BYTES`): [performance](performance.md#the-cache); reading
files (`ASSEMBLER_ALLOW_PATHS`): [SECURITY.md](../SECURITY.md); robosuite's entry points
(`python -m assembler.robosuite`): [robosuite](robosuite.md).

## Global options

Before the command or after it: `assembler --specs my_robots/ build MyArm` is
`assembler build MyArm --specs my_robots/`."""


def cli_markdown() -> str:
    """The command-line reference: the global options, then each command with every argument and
    flag, in ``assembler --help``'s order, with the help text the parser prints."""
    parser = build_parser()
    (subparsers,) = [a for a in parser._actions if isinstance(a, argparse._SubParsersAction)]
    lines = [
        "# Command-line reference",
        "",
        f"<!-- Generated from the parser of `assembler --help` by `{REGENERATE}`; tests/test_docs.py",
        "keeps it current. -->",
        "",
        CLI_INTRODUCTION,
        "",
        "| option | what it does |",
        "|---|---|",
        *_rows(parser, {"command"}),
        "",
        "## Commands",
        "",
        "| command | what it does |",
        "|---|---|",
        *[f"| [`{c.name}`](#assembler-{c.name}) | {_text(c.help)} |" for c in COMMANDS],
    ]
    global_options = {action.dest + "_after" for action in parser._actions}
    for command in COMMANDS:
        sub = subparsers.choices[command.name]
        lines += ["", f"## assembler {command.name}", "", f"{command.help[0].upper()}{command.help[1:]}."]
        lines += [f"\n{_text(text)}" for text in (command.description, command.epilog) if text]
        lines += ["", "| argument | what it does |", "|---|---|", *_rows(sub, global_options)]
    return "\n".join(lines) + "\n"


PAGES = {API_PAGE: api_markdown, CLI_PAGE: cli_markdown}
"""Each generated page and the function writing it."""


def main() -> int:
    for page, write in PAGES.items():
        (ROOT / page).write_text(write())
        print(f"wrote {page}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
