"""The slow path of a request: resolve it with the registry (reading and validating specs), answer
it through the compile service, and record it so the next process answers it from the cache
(:mod:`assembler.answers.records`).

A request is recorded only when its answer can be found again from the request alone: every part
is made from spec files (their files and times as read are in the record), and every spec the
registry holds was read from the folders the request names (the shipped specs, ``--specs`` folders,
the robot's spec file). A process that registered anything else (a spec given as text, a folder
the request does not name, a hand-written class) does not record: another process could not
resolve the same names the same way.
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from pathlib import Path

import mujoco

from assembler.answers.records import KeyedRequest, Origin, record
from assembler.files.paths import shipped_specs_dir
from assembler.models import REGISTRIES, PartModel, RobotModel
from assembler.models.motor_table import MOTORS
from assembler.registry.catalog import add_spec_folders, register_specs
from assembler.registry.instances import assemble
from assembler.spec.documents import Overrides
from assembler.spec.part_arguments import is_spec_file


def part_origins(cls: type[PartModel]) -> tuple[Origin, ...]:
    """The files a part was made from: its spec's (and its parents'), and the motor specs its
    ``motors:`` entries name (a changed motor spec changes the part)."""
    loaded = getattr(cls, "loaded", None)
    document = getattr(loaded, "document", None)
    motors = MOTORS.origins([entry.motor for entry in cls.spec.motors]) if document is not None else ()
    return tuple(Origin(*origin) for origin in (*getattr(document, "origins", ()), *motors))


def _within(path: str, roots: Sequence[Path]) -> bool:
    return any(Path(path).is_relative_to(root) for root in roots)


def _registry_within(roots: Sequence[Path]) -> bool:
    """True when every registered class was made from spec files below ``roots`` (a shipped spec
    not read yet is below them by construction: only the shipped folder's names are held)."""
    for table in REGISTRIES.values():
        for cls in table.made():
            origins = part_origins(cls)
            if not origins or not all(_within(origin.path, roots) for origin in origins):
                return False
    motors = MOTORS.origins()  # a motor spec of a folder the request does not name: no record
    return all(_within(origin[0], roots) for origin in motors)


def record_answer(
    request: KeyedRequest,
    robot: RobotModel,
    folders: Iterable[Path],
    robot_file: Path | None,
    notes: Iterable[str] = (),
) -> bool:
    """Record that ``request`` is answered by ``robot``'s entry in the compiled-model cache, with
    the user's spec ``folders`` and ``robot_file`` registered besides the shipped specs; returns
    whether a record was written (see the module's rules)."""
    key = robot.entry_key  # the entry the robot's model was just answered from or stored under
    if key is None:
        return False
    roots = [shipped_specs_dir().resolve(), *(Path(folder).resolve() for folder in folders)]
    within = [*roots, *([robot_file.resolve()] if robot_file is not None else [])]
    parts = [type(robot), *(type(part) for part in robot.models)]
    origins = [origin for part in parts for origin in part_origins(part)]
    if not all(part_origins(part) for part in parts) or not _registry_within(within):
        return False
    return record(request, key, origins, roots, notes, type(robot).__name__)


def resolve(
    robot: str,
    idn: int | str,
    base: str | None,
    grippers: Mapping[str, str | None] | None,
    overrides: Overrides,
    specs: Sequence[str | Path],
) -> tuple[RobotModel, Path | None]:
    """The assembled robot a request names, with ``specs`` folders registered first; and the
    robot's spec file when it was given as one."""
    add_spec_folders(specs)
    robot_file = Path(robot).resolve() if is_spec_file(robot) else None
    name = register_specs(robot_file)[0].__name__ if robot_file is not None else robot
    return assemble(name, idn=idn, base=base, grippers=grippers, overrides=overrides), robot_file


def load_and_record(
    request: KeyedRequest,
    robot: str,
    idn: int | str,
    base: str | None,
    grippers: Mapping[str, str | None] | None,
    overrides: Overrides,
    specs: Sequence[str | Path],
    cache: bool,
) -> mujoco.MjModel:
    """:func:`assembler.answers.load_model.load_model`'s slow path: assemble, compile (or load), record."""
    assembled, robot_file = resolve(robot, idn, base, grippers, overrides, specs)
    model = assembled.get_model(cache=cache)
    if cache:
        record_answer(request, assembled, [Path(folder) for folder in specs], robot_file)
    return model
