"""``python -m benchmarks.call_trace``: which of our functions a cold and a warm ``assembler build``
runs, counted with a call tracer (``sys.setprofile``), and how often the request and the cache key
are computed. Counts, not seconds: they do not depend on the machine's load.

Prints, per run: the distinct functions and modules of ``assembler`` called, which package calls
which (an edge ``cache -> cli`` is a call from the cache into the command layer), how often the
command layer is called back from below it, and the calls of the functions that compute a
request's key and a model's cache key.
"""

from __future__ import annotations

import os
import sys
import tempfile
from collections import Counter
from pathlib import Path
from types import FrameType
from typing import Any

PACKAGE = str(Path(__file__).resolve().parents[1] / "assembler")
KEYS = ("cache_key", "request_key", "build_request")
"""Functions whose every call is reported: computing a request and the cache keys."""


def _package(filename: str) -> str:
    parts = Path(filename).relative_to(PACKAGE).with_suffix("").parts
    return parts[0] if len(parts) > 1 else parts[0].removesuffix("__init__") or "assembler"


def trace(argv: list[str]) -> dict[str, Any]:
    """Run ``assembler`` with ``argv`` in this process under a profiler hook; what it called."""
    from assembler.cli import main  # noqa: PLC0415 - the tracer must see the imports' calls too

    functions: Counter[tuple[str, str]] = Counter()
    edges: Counter[tuple[str, str]] = Counter()

    def hook(frame: FrameType, event: str, _: object) -> None:
        if event != "call" or not frame.f_code.co_filename.startswith(PACKAGE):
            return
        module = frame.f_code.co_filename
        functions[(module, frame.f_code.co_name)] += 1
        caller = frame.f_back
        while caller is not None and not caller.f_code.co_filename.startswith(PACKAGE):
            caller = caller.f_back
        if caller is not None and frame.f_code.co_name != "<module>":
            edges[(_package(caller.f_code.co_filename), _package(module))] += 1

    sys.setprofile(hook)
    try:
        code = main(argv)
    finally:
        sys.setprofile(None)
    return {
        "exit": code,
        "functions": len(functions),
        "modules": len({module for module, _ in functions}),
        "edges": sorted(f"{a}->{b}" for a, b in edges if a != b),
        "cli_reentries": sum(n for (a, b), n in edges.items() if b == "cli" and a != "cli"),
        "keys": {name: sum(n for (_, f), n in functions.items() if f == name) for name in KEYS},
    }


def main() -> int:
    robot = sys.argv[1] if len(sys.argv) > 1 else "Sparrow7"
    with tempfile.TemporaryDirectory() as folder:
        os.environ["ASSEMBLER_CACHE_DIR"] = str(Path(folder) / "cache")
        out = str(Path(folder) / "out.xml")
        for run in ("cold", "warm"):
            if run == "warm":  # a new process would start here; drop what this one remembers
                for name in [m for m in sys.modules if m.startswith("assembler")]:
                    del sys.modules[name]
            found = trace(["build", robot, "-o", out])
            print(
                f"{run}: exit {found['exit']}, {found['functions']} functions in {found['modules']} modules, "
                f"command layer called back {found['cli_reentries']}x, keys {found['keys']}"
            )
            print(f"  package calls: {', '.join(found['edges'])}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
