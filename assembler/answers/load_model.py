"""``assembler.load_model``: a robot's compiled model in as little time as MuJoCo's own load of it.

A request made before in this environment is answered from the compiled-model cache through its
request record (:mod:`assembler.answers.records`) without importing the schema or reading any spec;
anything else takes the full path (``assemble(...).get_model()``) and records the request for
next time. This module imports only the cache layer and MuJoCo: that is what keeps a warm load
close to ``mujoco.MjModel.from_binary_path`` of the cached file.
"""

from __future__ import annotations

import importlib
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import mujoco

from assembler.answers.records import KeyedRequest, answered_model, keyed
from assembler.spec.part_arguments import DEFAULT, spec_file_path


def _plain(overrides: Any) -> Any:
    """Overrides as plain data for the request (a mapping or a list of ``PATH=VALUE`` strings);
    anything else is kept as it is, which makes the request unrecordable, never wrong."""
    if isinstance(overrides, Mapping):
        return {str(key): value for key, value in overrides.items()}
    if isinstance(overrides, (list, tuple)) and all(isinstance(item, str) for item in overrides):
        return list(overrides)
    return overrides


def assembly_request(
    robot: str,
    idn: int | str = 0,
    base: str | None = DEFAULT,
    grippers: Mapping[str, str | None] | None = None,
    overrides: Any = None,
    specs: Sequence[str | Path] = (),
    kind: str = "load_model",
) -> KeyedRequest:
    """The request ``load_model(robot, idn, base, grippers, overrides, specs=specs)`` makes; it is
    ``assemble(...).get_model()``, so ``assemble`` makes the same request and one record answers
    either (``kind`` ``"create_robot"``: ``create_robot(robot, idn, overrides=...)``, no base or
    grippers)."""
    spec_file = spec_file_path(robot)
    return keyed(
        {
            "kind": kind,
            "robot": str(spec_file) if spec_file is not None else robot,
            "idn": idn,
            "base": base,
            "grippers": dict(grippers) if grippers is not None else None,
            "overrides": _plain(overrides),
            "specs": [str(Path(folder).resolve()) for folder in specs],
        }
    )


def load_model(
    robot: str,
    idn: int | str = 0,
    base: str | None = DEFAULT,
    grippers: Mapping[str, str | None] | None = None,
    overrides: Any = None,
    cache: bool = True,
    specs: Sequence[str | Path] = (),
) -> mujoco.MjModel:
    """The compiled model of ``assemble(robot, idn, base, grippers, overrides).get_model()``.

    ``robot`` is a registered name or a spec file; ``specs`` are spec folders to register first
    (the CLI's ``--specs``). A request answered before in this environment is loaded from the
    cache without reading any spec, as long as every spec file, spec folder and model input it
    was made from is unchanged; ``cache=False`` compiles (and records nothing).
    """
    request = assembly_request(robot, idn, base, grippers, overrides, specs)
    if cache:
        model = answered_model(request)
        if model is not None:
            return model
    # The slow path reads specs: imported only now, so a repeated request never pays for it.
    slow = importlib.import_module("assembler.answers.request")
    return slow.load_and_record(request, robot, idn, base, grippers, overrides, specs, cache)
