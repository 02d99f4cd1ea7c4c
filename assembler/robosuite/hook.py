"""Running the bridge when robosuite loads, and the start-up hook that does it in scripts nobody edits.

``python -m assembler.robosuite --install-hook`` writes a ``.pth`` file whose one line, at interpreter
start and only while ``ASSEMBLER_ROBOSUITE_SPECS`` or ``ASSEMBLER_ROBOSUITE_EXPERIMENT`` is set, runs
this file by its path (under the name :data:`START`): no ``assembler`` package is imported, so an
unrelated process pays for reading this file and one import-system lookup per import, and once the
package is uninstalled the line finds no file and does nothing. The finder it installs waits for the
process to import robosuite, then imports :mod:`assembler.robosuite`, whose bridge registers what the
variables name. Importing robosuite at start instead would run in every Python process, including the
ones robosuite's own imports spawn.

This module imports nothing but what the interpreter has loaded before ``site`` runs, for the same reason.
"""

from __future__ import annotations

import importlib
import importlib.machinery
import sys
from collections.abc import Callable, Sequence
from types import ModuleType

VARIABLES: tuple[str, ...] = ("ASSEMBLER_ROBOSUITE_SPECS", "ASSEMBLER_ROBOSUITE_EXPERIMENT")
"""The hook does anything only when one of these is set."""

START = "assembler_robosuite_start"
"""The name this file runs under from the ``.pth`` line (not a package module: no package is imported)."""


def pth_line(hook_file: str) -> str:
    """The ``.pth`` file's line (site runs lines that start with ``import``): run ``hook_file`` while a
    variable is set and the file exists. The parentheses matter: ``a or b and c`` is ``a or (b and c)``;
    the file is read with ``os.open``/``os.read``/``os.close`` because ``os`` is loaded already and a
    file object left to the collector would be a ResourceWarning."""
    variables = " or ".join(f"os.environ.get('{name}')" for name in VARIABLES)
    read = "os.read(d := os.open(f, os.O_RDONLY), 1 << 20) + (os.close(d) or b'')"
    return (
        f"import os; f = {hook_file!r}; ({variables}) and os.path.isfile(f) and "
        f"exec(compile({read}, f, 'exec'), {{'__name__': '{START}', '__file__': f}})\n"
    )


class AfterRobosuite:
    """Finds nothing itself; when robosuite is imported, runs its callbacks after robosuite has loaded.
    (A meta path finder needs only ``find_spec``; ``importlib.abc`` would import ``importlib.resources``,
    ``pathlib`` and ``tempfile`` into every process the hook starts in: 0.2 s on a busy machine.)"""

    def __init__(self) -> None:
        self.callbacks: list[Callable[[], object]] = []

    def find_spec(
        self, name: str, path: Sequence[str] | None, target: ModuleType | None = None
    ) -> importlib.machinery.ModuleSpec | None:
        if name != "robosuite":
            return None
        sys.meta_path.remove(self)
        spec = importlib.machinery.PathFinder.find_spec(name, path)
        if spec is None or spec.loader is None:
            return spec
        loader = spec.loader
        load = loader.exec_module
        callbacks = self.callbacks

        def exec_module(module: ModuleType) -> None:
            load(module)
            for callback in callbacks:
                callback()

        loader.exec_module = exec_module  # type: ignore[method-assign]
        return spec


def when_robosuite_loads(callback: Callable[[], object]) -> None:
    """Call ``callback`` now if robosuite is imported, else right after the process imports it."""
    if "robosuite" in sys.modules:
        callback()
        return
    # by name: the copy of this file the .pth line ran defines its own AfterRobosuite class
    finders = [f for f in sys.meta_path if type(f).__name__ == AfterRobosuite.__name__]
    if not finders:
        finders = [AfterRobosuite()]
        sys.meta_path.insert(0, finders[0])
    callbacks: list[Callable[[], object]] = getattr(finders[0], "callbacks")  # noqa: B009
    # by module and name too: site may run the .pth line twice (a venv's lib64 -> lib link), each run
    # defining its own copy of the same function
    key = (callback.__module__, callback.__qualname__)
    if key not in [(known.__module__, known.__qualname__) for known in callbacks]:
        callbacks.append(callback)


def _import_the_bridge_package() -> None:
    """Import :mod:`assembler.robosuite` (robosuite is loaded: its ``__init__`` runs the bridge); where
    the package is gone but this file is not (an editable install uninstalled), say so in one line."""
    try:
        importlib.import_module("assembler.robosuite")
    except ModuleNotFoundError as error:
        if error.name not in ("assembler", "assembler.robosuite"):
            raise
        print(
            f"assembler.robosuite: the start-up hook {__file__} runs, but the package is not installed "
            "here; remove the hook's .pth file or reinstall robot-assembler",
            file=sys.stderr,
        )


if __name__ == START:  # run by the .pth line at interpreter start
    when_robosuite_loads(_import_the_bridge_package)
