"""``python -m assembler.robosuite``: run a script with spec robots in robosuite, or (un)install the
start-up hook that does it for every script while ``ASSEMBLER_ROBOSUITE_SPECS`` or
``ASSEMBLER_ROBOSUITE_EXPERIMENT`` is set.

    python -m assembler.robosuite train.py --lr 3e-4   # train.py sees the spec robots
    python -m assembler.robosuite --install-hook        # every script, while a variable is set
    python -m assembler.robosuite --remove-hook
    python -m assembler.robosuite --check               # which of robosuite's statements are patched

A problem with what the variables name is one line each, and the script does not run (exit 1).
"""

from __future__ import annotations

import importlib
import runpy
import sys
import sysconfig
from pathlib import Path
from types import ModuleType

import assembler.robosuite  # noqa: F401  (registers the spec robots when robosuite loads)
from assembler.cli.endings import end_cleanly
from assembler.errors import AssemblerError
from assembler.files.writing import write_atomically
from assembler.robosuite import hook

PTH_NAME = "assembler-robosuite.pth"
NEEDS_ROBOSUITE = "assembler.robosuite needs robosuite"
"""How the bridge's ImportError starts when robosuite is not installed."""


def hook_path() -> Path:
    """Where the ``.pth`` file goes: this environment's site-packages."""
    return Path(sysconfig.get_paths()["purelib"]) / PTH_NAME


def setup(argv: list[str]) -> int:
    """Handle the options; for a script, register (every problem as one line) and return -1."""
    if not argv or argv[0] in ("-h", "--help"):
        print(__doc__)
        return 0 if argv else 2
    if argv[0] == "--install-hook":
        write_atomically(hook_path(), hook.pth_line(str(Path(hook.__file__).resolve())))
        print(
            f"wrote {hook_path()}: scripts register spec robots with robosuite while "
            "ASSEMBLER_ROBOSUITE_SPECS "
            "or ASSEMBLER_ROBOSUITE_EXPERIMENT is set"
        )
        return 0
    if argv[0] == "--remove-hook":
        hook_path().unlink(missing_ok=True)
        print(f"removed {hook_path()}")
        return 0
    if argv[0] == "--check":
        return check()
    bridge = _bridge()  # imports robosuite: registers now
    return 1 if bridge.ENVIRONMENT_PROBLEMS else -1  # its problems are printed, one line each


def check() -> int:
    """Print the MuJoCo and robosuite in use and, per patch of robosuite's statements, its state."""
    bridge = _bridge()
    compat = importlib.import_module("assembler.robosuite.compat")
    robosuite = sys.modules["robosuite"]
    print(f"MuJoCo {compat.mujoco.__version__}, robosuite {robosuite.__version__}")
    for line in compat.report():
        print(line)
    return 1 if bridge.ENVIRONMENT_PROBLEMS else 0


def _bridge() -> ModuleType:
    """The bridge, imported (robosuite with it); without robosuite, one line says what to install."""
    try:
        return importlib.import_module("assembler.robosuite.bridge")
    except ImportError as error:
        if not str(error).startswith(NEEDS_ROBOSUITE):
            raise
        raise AssemblerError(str(error)) from None


def main(argv: list[str]) -> int:
    """Set up, then run the script as ``python script.py`` would (its errors are its own)."""
    code = end_cleanly(lambda: setup(argv))
    if code != -1:
        return code
    script = argv[0]
    sys.argv = list(argv)
    sys.path.insert(0, str(Path(script).resolve().parent))
    runpy.run_path(script, run_name="__main__")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
