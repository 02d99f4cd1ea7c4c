"""The motor specs by name: the shipped catalogue (``specs/motors/``, read when a motor is first
looked up) and the motors of the spec folders a user registers.

Motors are data, not classes: a part's ``motors:`` entries name them, and the part looks them up
here when it prepares its joints. One name has one definition; a second, different spec of the same
name is an error that names both files.
"""

from __future__ import annotations

import contextlib
import threading
from collections.abc import Iterator, Sequence

from assembler.errors import Problem, RegistryError
from assembler.files.paths import shipped_specs_dir
from assembler.models.motor_rules import Drive
from assembler.models.registering import unknown_name
from assembler.spec.documents import LoadedSpec
from assembler.spec.fieldpath import FieldPath
from assembler.spec.schema import JointMotor, MotorSpec
from assembler.spec.spec_files import load_motors, read_spec_files

SHIPPED_FOLDER = "motors"
"""The shipped catalogue's folder under the shipped specs."""

NAME = FieldPath(("name",))


class MotorTable:
    """Motor specs by name, with the file each came from."""

    def __init__(self) -> None:
        self._specs: dict[str, LoadedSpec[MotorSpec]] = {}
        self._shipped_read = False
        self._lock = threading.RLock()

    def _read_shipped(self) -> None:
        with self._lock:
            if self._shipped_read:
                return
            self._shipped_read = True
            folder = shipped_specs_dir() / SHIPPED_FOLDER
            if folder.is_dir():
                found = read_spec_files([folder])
                self.add(load_motors(found.motors))

    def add(self, batch: Sequence[LoadedSpec[MotorSpec]]) -> None:
        """Add motor specs; a name another file defines differently is a :class:`RegistryError` (then
        none of the batch is added)."""
        if not batch:
            return  # the shipped catalogue stays unread until a motor is looked up
        self._read_shipped()
        with self._lock:
            problems: list[Problem] = []
            seen: dict[str, LoadedSpec[MotorSpec]] = {}
            for loaded in batch:
                name = loaded.spec.name
                held = self._specs.get(name)
                if held is not None and held.source == loaded.source:
                    held = None  # the same file read again (edited or not): the new reading wins
                earlier = seen.setdefault(name, held or loaded)
                if earlier is not loaded and earlier.spec != loaded.spec:
                    message = f"motor '{name}' is also defined by {earlier.source}; rename one"
                    problems.append(loaded.problem(NAME, message))
            if problems:
                raise RegistryError(problems)
            for loaded in batch:
                held = self._specs.get(loaded.spec.name)
                if held is None or held.source == loaded.source:
                    self._specs[loaded.spec.name] = loaded

    def names(self) -> list[str]:
        """Every motor's name, sorted."""
        self._read_shipped()
        return sorted(self._specs)

    def lookup(self, name: str) -> LoadedSpec[MotorSpec]:
        """The motor spec ``name``; the error names the closest motor, or lists them."""
        self._read_shipped()
        found = self._specs.get(name)
        if found is None:
            raise RegistryError(unknown_name("motor", name, sorted(self._specs)))
        return found

    def state(self) -> tuple[dict[str, LoadedSpec[MotorSpec]], bool]:
        """What :meth:`restore` needs to forget the motors added after it."""
        return dict(self._specs), self._shipped_read

    def restore(self, state: tuple[dict[str, LoadedSpec[MotorSpec]], bool]) -> None:
        """Hold again exactly the motors held at ``state``."""
        with self._lock:
            self._specs.clear()
            self._specs.update(state[0])
            self._shipped_read = state[1]

    def inputs(self, names: Sequence[str]) -> dict[str, object]:
        """The motor specs ``names`` name, as data (what a build that uses them depends on); a name
        not known is left out (the build reports it)."""
        found: dict[str, object] = {}
        for name in names:
            try:
                found[name] = self.lookup(name).spec.model_dump(mode="json")
            except RegistryError:
                continue
        return found

    def limited_to(self, torque: float, tolerance: float = 0.01) -> list[str]:
        """The motors whose torque limit with their own gearbox (peak or stall torque × N × η) is
        ``torque`` within ``tolerance`` (a fraction): the candidates for a joint whose file gives that
        effort limit, sorted."""
        found = []
        for name in self.names():
            motor = self.lookup(name).spec
            limit = Drive(motor, JointMotor(match="*", motor=name), 0).torque_limit()
            if limit is not None and abs(limit.value - torque) <= tolerance * torque:
                found.append(name)
        return found

    def origins(self, names: Sequence[str] | None = None) -> tuple[tuple[str, int, int], ...]:
        """(file, size, mtime_ns when read) of the motor specs ``names`` name (unknown names left
        out), or of every motor spec held: what a recorded answer must see unchanged."""
        with self._lock:
            held = self._specs if names is None else {n: self._specs[n] for n in names if n in self._specs}
            return tuple(origin for loaded in held.values() for origin in loaded.document.origins)

    @contextlib.contextmanager
    def transaction(self) -> Iterator[None]:
        """Motors added in the block are removed again if the block fails."""
        with self._lock:
            before = self.state()
            try:
                yield
            except BaseException:
                self.restore(before)
                raise


MOTORS = MotorTable()
"""Every motor spec known to this process."""
