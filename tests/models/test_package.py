"""The models package gives its names on first use: its registries are read without importing a
model class or the schema, and what type checkers read of it is its table of names."""

from __future__ import annotations

import importlib
import subprocess
import sys
from pathlib import Path

import assembler.models
from tests.facades import type_checking_imports

INIT = Path(assembler.models.__file__)


def test_what_type_checkers_read_is_the_table_of_names() -> None:
    imports = type_checking_imports(INIT)
    assert [name for _, name, alias in imports if alias != name] == []  # each `X as X`: re-exported
    assert sorted((module, name) for module, name, _ in imports) == sorted(
        (module, name) for module, names in assembler.models.HOMES.items() for name in names
    )


def test_every_name_is_the_object_its_module_gives() -> None:
    for module, names in assembler.models.HOMES.items():
        for name in names:
            assert getattr(assembler.models, name) is getattr(importlib.import_module(module), name)


def test_a_name_the_package_does_not_give_is_an_attribute_error() -> None:
    try:
        assembler.models.RobotModle  # noqa: B018
    except AttributeError as error:
        assert "RobotModle" in str(error)
    else:
        raise AssertionError("a misspelt name was given")


def test_the_registries_are_read_without_a_model_class_or_the_schema() -> None:
    script = (
        "import sys\n"
        "from assembler.models.registering import REGISTRIES\n"
        "from assembler.registry.shipped import hold_shipped_names\n"
        "hold_shipped_names()\n"
        "assert REGISTRIES['robot'].held_names(), 'the shipped names are held'\n"
        "print(sorted(n for n in sys.modules if n == 'pydantic' or n.startswith('assembler.spec.schema')"
        " or n in ('assembler.models.part', 'assembler.models.robot_model')))\n"
    )
    out = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"
    assert type(assembler.models.REGISTERED_ROBOTS) is type(assembler.models.REGISTRIES["robot"])
    assert assembler.models.REGISTERED_ROBOTS is assembler.models.REGISTRIES["robot"]
