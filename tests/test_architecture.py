"""The package's structure keeps its promises: imports go one way (no module imports a module that
imports it back, at any distance), none hides in a function, and every module says what it holds."""

from __future__ import annotations

import ast
from pathlib import Path

PACKAGE = Path(__file__).resolve().parent.parent / "assembler"


def _module_name(path: Path) -> str:
    parts = path.relative_to(PACKAGE.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


MODULES = {_module_name(path): path for path in PACKAGE.rglob("*.py")}


def _owner(target: str) -> str | None:
    """The project module an import target names (``assembler.models.part.PartModel`` -> its module)."""
    while target and target not in MODULES:
        target = target.rpartition(".")[0]
    return target or None


def _imports(tree: ast.AST) -> list[tuple[ast.AST, str]]:
    found: list[tuple[ast.AST, str]] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            found += [(node, alias.name) for alias in node.names]
        elif isinstance(node, ast.ImportFrom) and node.module and node.level == 0:
            found += [(node, f"{node.module}.{alias.name}") for alias in node.names]
    return [(node, name) for node, name in found if name.startswith("assembler")] + _deferred_imports(tree)


def _deferred_imports(tree: ast.AST) -> list[tuple[ast.AST, str]]:
    """``importlib.import_module("assembler.x")`` calls with a literal name: imports too, made late."""
    return [
        (node, node.args[0].value)
        for node in ast.walk(tree)
        if isinstance(node, ast.Call)
        and isinstance(node.func, ast.Attribute)
        and node.func.attr == "import_module"
        and node.args
        and isinstance(node.args[0], ast.Constant)
        and isinstance(node.args[0].value, str)
        and node.args[0].value.startswith("assembler")
    ]


def _graph() -> dict[str, set[str]]:
    """Who imports whom; an import made late on purpose (DEFERRED) runs after both modules loaded, so
    it closes no cycle at import time."""
    graph: dict[str, set[str]] = {}
    for name, path in MODULES.items():
        imported = _imports(ast.parse(path.read_text()))
        targets = {_owner(target) for _, target in imported if (name, target) not in DEFERRED}
        graph[name] = {t for t in targets if t is not None and t != name}
    return graph


def _cycles(graph: dict[str, set[str]]) -> list[list[str]]:
    """Strongly connected components with more than one module (Tarjan)."""
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    found: list[list[str]] = []

    def visit(node: str) -> None:
        index[node] = low[node] = len(index)
        stack.append(node)
        for target in graph[node]:
            if target not in index:
                visit(target)
                low[node] = min(low[node], low[target])
            elif target in stack:
                low[node] = min(low[node], index[target])
        if low[node] == index[node]:
            component = []
            while True:
                member = stack.pop()
                component.append(member)
                if member == node:
                    break
            if len(component) > 1:
                found.append(sorted(component))

    for node in graph:
        if node not in index:
            visit(node)
    return found


def test_no_module_imports_itself_back_through_others() -> None:
    assert _cycles(_graph()) == []


LAYERS: tuple[tuple[str, ...], ...] = (
    ("assembler.version",),
    ("assembler.spec.fieldpath",),  # a field's path: a plain value the errors name
    ("assembler.errors",),
    ("assembler.files",),
    ("assembler.spec",),
    ("assembler.mjcf",),
    ("assembler.cache",),
    ("assembler.urdf",),
    ("assembler.compiler",),
    ("assembler.models",),
    ("assembler.registry",),
    ("assembler.patch",),
    ("assembler.answers",),
    ("assembler.worlds",),
    ("assembler.checks",),  # what a lint check is; the checks live with what they know, above
    ("assembler.robosuite", "assembler.warp", "assembler.gpu", "assembler.mjlab"),
    ("assembler.tools",),
    ("assembler.importers",),
    ("assembler.cli",),
    ("assembler.robosuite.__main__",),  # `python -m assembler.robosuite`: a command, ended as the CLI ends
    ("assembler",),  # the package root: the public API, and the one place that wires layers together
)
"""The packages bottom to top: a module imports only from its own package or the layers below it
(a model produces values, the compiler takes them; nothing calls back up). Within a layer of
several packages, none imports another. The longest name that prefixes a module decides its layer."""


def _layer(module: str) -> tuple[int, str]:
    matches = [
        (len(name), index, name)
        for index, names in enumerate(LAYERS)
        for name in names
        if module == name or module.startswith(f"{name}.")
    ]
    _, index, name = max(matches)
    return index, name


def test_packages_import_only_their_own_layer_and_the_layers_below() -> None:
    upward = []
    for name, path in MODULES.items():
        here, package = _layer(name)
        for node, target in _imports(ast.parse(path.read_text())):
            owner = _owner(target)
            if owner is None or owner == name:
                continue
            there, other = _layer(owner)
            if there > here or (there == here and other != package):
                upward.append(f"{name}:{getattr(node, 'lineno', 0)} imports {owner}")
    assert upward == []


def test_every_package_has_its_place_in_the_order() -> None:
    named = {name for names in LAYERS for name in names}
    packages = {_module_name(path) for path in PACKAGE.glob("*/__init__.py")}
    assert sorted(packages - named) == []


FACADES = ("assembler", "assembler.models")
"""Packages whose ``__init__`` gives names imported on first use, the names also imported under
TYPE_CHECKING for type checkers: the public API (``import assembler`` must stay light, issue 16),
and the model classes (robosuite's bridge reads the registries without importing a class or the
schema, issue 33)."""


DEFERRED = {
    ("assembler.cli", "assembler.cli.cached_build"): "a cached build is answered before the commands load",
    ("assembler.cli", "assembler.cli.common"): "the commands' modules load after parsing",
    (
        "assembler.robosuite.hook",
        "assembler.robosuite",
    ): "the start-up hook imports the bridge once robosuite loads",
    (
        "assembler.robosuite.__main__",
        "assembler.robosuite.compat",
    ): "after robosuite is found (else one line)",
    (
        "assembler.robosuite.__main__",
        "assembler.robosuite.bridge",
    ): "after robosuite is found (else one line)",
    ("assembler.answers.load_model", "assembler.answers.request"): "a cached model is answered without specs",
    ("assembler.answers.deferred", "assembler.registry.instances"): "a robot asked for before reads no spec",
    (
        "assembler.robosuite.autoload",
        "assembler.registry.catalog.register_specs",
    ): "a user's spec folders are read (the schema imported) only when registered: a warm make reads none",
    (
        "assembler.robosuite.autoload",
        "assembler.registry.catalog.with_overrides",
    ): "an experiment file is read only when registered: a warm make reads none",
    (
        "assembler.robosuite.autoload",
        "assembler.worlds.experiment.build_experiment",
    ): "an experiment file is read only when registered: a warm make reads none",
    (
        "assembler.robosuite.autoload",
        "assembler.worlds.experiment.read_experiment",
    ): "an experiment file is read only when registered: a warm make reads none",
    (
        "assembler.robosuite.conventions",
        "assembler.spec.schema.RobotSpec",
    ): "for type checkers only: robosuite's questions of a recorded part import no schema",
    (
        "assembler.robosuite.make_records",
        "assembler.answers.request.part_origins",
    ): "only a miss records a part's spec files: a warm make reads no spec",
    (
        "assembler.models.gripper_actions",
        "assembler.spec.schema.gripper_actions.GripperActions",
    ): "for type checkers only: a recorded gripper's action map is rebuilt without the schema",
    (
        "assembler.robosuite.robot_class",
        "assembler.robosuite.parts",
    ): "our part is made (the model classes and the schema imported) only when its make record is not enough",
    (
        "assembler.robosuite.part_classes",
        "assembler.robosuite.parts",
    ): "our part is made (the model classes and the schema imported) only when its make record is not enough",
    (
        "assembler.registry.shipped",
        "assembler.registry.catalog",
    ): "a shipped name is held without the schema; the catalog reads its spec when it is first made",
    ("assembler.answers.deferred", "assembler.answers.request"): "a robot asked for before reads no spec",
    (
        "assembler.answers.deferred",
        "assembler.files.bundles",
    ): "a cached save copies assets (ElementTree) only for a model naming a file in the cache",
    (
        "assembler.robosuite",
        "assembler.robosuite.bridge",
    ): "the bridge imports robosuite, when robosuite loads",
    (
        "assembler.robosuite.checks",
        "assembler.robosuite.controllers",
    ): "lint reads robosuite's controller configurations (importing robosuite) only for a spec naming one",
}
"""The imports made late on purpose, each with why; any other import must be at the module's top."""


def test_no_project_module_is_imported_inside_a_function_or_only_for_type_checking() -> None:
    hidden = []
    for name, path in MODULES.items():
        if name in FACADES:
            continue
        tree = ast.parse(path.read_text())
        top_level = {id(node) for node in tree.body}
        hidden += [
            f"{name}:{getattr(node, 'lineno', 0)} imports {target}"
            for node, target in _imports(tree)
            if id(node) not in top_level and (name, target) not in DEFERRED
        ]
    assert hidden == []


def test_every_deferred_import_is_still_made() -> None:
    made = {
        (name, target)
        for name, path in MODULES.items()
        for _, target in _imports(ast.parse(path.read_text()))
    }
    assert set(DEFERRED) <= made


def test_every_module_has_a_docstring() -> None:
    missing = [
        name for name, path in MODULES.items() if ast.get_docstring(ast.parse(path.read_text())) is None
    ]
    assert missing == []


def test_the_package_map_names_every_package_in_one_line() -> None:
    page = PACKAGE.parent / "docs" / "architecture.md"
    readme = (page if page.is_file() else PACKAGE.parent / "README.md").read_text()
    packages = sorted(p.name for p in PACKAGE.iterdir() if (p / "__init__.py").is_file())
    unmapped = [name for name in packages if f"`{name}/`" not in readme and f"`{name}/`," not in readme]
    assert unmapped == []


def test_only_the_public_api_sits_at_the_top_of_the_package() -> None:
    loose = sorted(p.name for p in PACKAGE.glob("*.py"))
    assert loose == ["__init__.py", "errors.py", "version.py"]
