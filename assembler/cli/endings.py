"""How a command ends, whatever happens: one line and the right exit code, never a traceback.

- a problem in the user's input (:class:`AssemblerError`): one line per problem, exit 1;
- Ctrl-C: ``interrupted``, exit 130 (128 + SIGINT, as shells report it);
- standard output closed early (``assembler list | head -1``): silent, exit 141 (128 + SIGPIPE), as
  ``git`` and ``cat`` end; the reader has what it wanted;
- standard output cannot be written (``> /dev/full``, or closed: ``>&-``): one line naming the
  reason, exit 1; a closed standard stream is first pointed at ``/dev/null``, so no file the command
  opens can take its number and receive what a library prints;
- a MuJoCo warning: one line ``warning: ...`` on standard error, the command goes on;
- MuJoCo failing to start its OpenGL backend as it is imported (``MUJOCO_GL`` set to a value it
  does not know, or ``osmesa`` without the OSMesa library): one line saying what to set, exit 1.

Anything else is a bug in the assembler and is allowed to crash with its traceback.
"""

from __future__ import annotations

import errno
import io
import os
import signal
import sys
import threading
import traceback
import warnings
from collections.abc import Callable
from pathlib import Path
from typing import TextIO

from assembler.errors import AssemblerError, MujocoWarning

INTERRUPTED = 130
BROKEN_PIPE = 141


def _print_warning(
    message: Warning | str,
    category: type[Warning],
    filename: str,
    lineno: int,
    file: TextIO | None = None,
    line: str | None = None,
) -> None:
    print(f"warning: {message}", file=sys.stderr)


def _silence_stdout() -> None:
    """Point standard output at /dev/null, so the interpreter's final flush cannot fail again."""
    null = os.open(os.devnull, os.O_WRONLY)
    os.dup2(null, sys.stdout.fileno())
    os.close(null)


class _ClosedOutput(io.TextIOBase):
    """Standard output that was closed when the command started: writing to it is an error."""

    def write(self, text: str) -> int:
        if not text:
            return 0
        raise OSError(errno.EBADF, "it was closed (>&-)")

    def fileno(self) -> int:
        return 1


def _fill_closed_streams() -> None:
    """Point a closed standard stream at /dev/null (before anything opens a file that would take
    its number); a closed standard output then refuses writes (:class:`_ClosedOutput`)."""
    for descriptor in (0, 1, 2):
        try:
            os.fstat(descriptor)
        except OSError:
            null = os.open(os.devnull, os.O_RDWR)
            if null != descriptor:
                os.dup2(null, descriptor)
                os.close(null)
    if sys.stdout is None:
        sys.stdout = _ClosedOutput()
    if sys.stderr is None:
        sys.stderr = open(os.devnull, "w")  # noqa: SIM115 - the process's stream, open until it ends


def end_cleanly(command: Callable[[], int], *, process_ends: bool = False) -> int:
    """Run ``command`` and turn every way it can end into an exit code and at most one line per problem.

    ``process_ends``: the process exits right after (a console script). A Ctrl-C that arrives from
    then on is ignored: the command has ended and said so, and while the interpreter exits (joining
    worker pools, then restoring the default handler) it would be a death by SIGINT (-2) instead.
    One that arrives while the command is ending, before it is ignored, ends it as interrupted."""
    try:
        return _ended(command, process_ends)
    except KeyboardInterrupt:  # raised between the command's end and ignoring Ctrl-C
        _ignore_ctrl_c(process_ends)
        print("interrupted", file=sys.stderr)
        return INTERRUPTED


def _ignore_ctrl_c(process_ends: bool) -> None:
    if process_ends and threading.current_thread() is threading.main_thread():
        signal.signal(signal.SIGINT, signal.SIG_IGN)  # kept as it is by the interpreter's exit


def _ended(command: Callable[[], int], process_ends: bool) -> int:
    """:func:`end_cleanly`'s work; a Ctrl-C in its last steps escapes it (to be said there)."""
    _fill_closed_streams()
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("always", MujocoWarning)
            warnings.showwarning = _print_warning  # restored by catch_warnings
            code = command()
            sys.stdout.flush()  # a closed or full stdout shows here, not in the interpreter's exit
            return code
    except AssemblerError as error:
        for problem in error.problems:
            print(str(problem), file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return INTERRUPTED
    except ImportError as error:
        if not _caused_by_ctrl_c(
            error
        ):  # Ctrl-C inside a compiled module's start reads "initialization failed"
            return _opengl_problem(error)
        print("interrupted", file=sys.stderr)
        return INTERRUPTED
    except BrokenPipeError:
        _silence_stdout()
        return BROKEN_PIPE
    except OSError as error:
        if _is_stdout(error):
            _silence_stdout()
            print(f"cannot write to standard output: {error.strerror}", file=sys.stderr)
            return 1
        return _opengl_problem(error)
    except Exception as error:
        return _opengl_problem(error)
    finally:
        _ignore_ctrl_c(process_ends)


GL_MODULES = ("gl_context", "osmesa", "egl", "glfw", "cgl")
"""MuJoCo's modules that start an OpenGL backend when ``mujoco`` is imported."""


def _opengl_problem(error: Exception) -> int:
    """Exit 1 with one line when ``error`` came from MuJoCo starting the backend ``MUJOCO_GL`` names
    (its modules, or PyOpenGL under them); re-raise it otherwise (a bug)."""
    backend = os.environ.get("MUJOCO_GL", "")
    files = [Path(frame.filename) for frame in traceback.extract_tb(error.__traceback__)]
    started = any(
        "OpenGL" in file.parts
        or ("mujoco" in file.parts and (file.stem in GL_MODULES or file.parent.name in GL_MODULES))
        for file in files
    )
    if not backend or not started:
        raise error
    reason = " ".join(str(error).split()) or type(error).__name__
    if not isinstance(error, RuntimeError):  # PyOpenGL's words say little: a library is missing
        reason = f"its OpenGL library cannot be loaded ({reason})"
    print(
        f"MuJoCo cannot start with MUJOCO_GL={backend}: {reason}; set MUJOCO_GL=egl (GPU or Mesa EGL) or "
        "MUJOCO_GL=osmesa (software rendering), install the library it needs, or unset it",
        file=sys.stderr,
    )
    return 1


def _caused_by_ctrl_c(error: BaseException) -> bool:
    """True when a KeyboardInterrupt is among the exceptions that led to ``error``."""
    seen: set[int] = set()
    current: BaseException | None = error
    while current is not None and id(current) not in seen:
        if isinstance(current, KeyboardInterrupt):
            return True
        seen.add(id(current))
        current = current.__cause__ or current.__context__
    return False


OUTPUT_ERRORS = frozenset({errno.ENOSPC, errno.EIO, errno.EFBIG, errno.EDQUOT, errno.EBADF})
"""Errors of writing a stream: the files the assembler writes itself report their own path."""


def _is_stdout(error: OSError) -> bool:
    """True when ``error`` came from writing standard output (it names no file)."""
    return error.filename is None and error.errno in OUTPUT_ERRORS
