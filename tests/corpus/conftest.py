"""The corpus's shared state: each model's spec written once by ``assembler new`` into a temporary
folder, pointing at the installed package's file, and registered."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from assembler.importers import write_new_spec
from assembler.importers.packages import environment
from assembler.registry.catalog import register_specs
from tests.corpus.cases import Case


class Corpus:
    """Specs written by ``assembler new`` into ``folder``, one per case, each once per session, and
    the environment set as ``new`` tells a user to set it (``before``: the variables' values first)."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder
        self.before: dict[str, str | None] = {}

    def model_file(self, case: Case) -> Path:
        path = case.path()
        if path is None:
            pytest.skip(f"{case.distribution} is not installed (pip install '.[corpus]')")
        return path

    def spec(self, case: Case) -> Path:
        """The spec ``assembler new`` writes for the case, as written (no field added)."""
        target = self.folder / f"{case.id}.yaml"
        if not target.exists():
            written, _ = write_new_spec(self.model_file(case), target)
            for variable, value in environment(written.packages).items():  # new's "to do: export ..."
                self.before.setdefault(variable, os.environ.get(variable))
                os.environ[variable] = value
            if case.name is not None:  # the one field a user changes here (see Case.name)
                text = target.read_text()
                target.write_text(re.sub(r"^name: \S+", f"name: {case.name}", text, count=1, flags=re.M))
        return target

    def name(self, case: Case) -> str:
        """The case's spec registered (again: each test starts from the shipped registry), by name."""
        (registered,) = register_specs(self.spec(case))
        return registered.__name__


@pytest.fixture(scope="session")
def corpus(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Corpus]:
    """The written specs; afterwards the environment as it was."""
    written = Corpus(tmp_path_factory.mktemp("corpus-specs"))
    try:
        yield written
    finally:
        for variable, value in written.before.items():
            if value is None:
                os.environ.pop(variable, None)
            else:
                os.environ[variable] = value
