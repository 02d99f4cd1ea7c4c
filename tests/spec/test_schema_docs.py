"""The committed JSON Schema and spec reference match the code, and shipped specs point editors at them."""

from __future__ import annotations

import json
import re
from pathlib import Path

import jsonschema
import pytest
import yaml

from assembler.cli import main
from assembler.spec.schema.json_schema import REFERENCE_FILE, SCHEMA_FILE, schema_text, spec_json_schema
from assembler.spec.schema.reference import markdown_reference, type_text

ROOT = Path(__file__).parents[2]
SHIPPED_SPECS = sorted((ROOT / "specs").rglob("*.yaml"))
SCHEMA_LINE = re.compile(r"# yaml-language-server: \$schema=(\S+)$")


def test_committed_json_schema_is_what_assembler_schema_prints() -> None:
    committed = (ROOT / SCHEMA_FILE).read_text()
    assert committed == schema_text(), (
        f"{SCHEMA_FILE} is stale; regenerate it: assembler schema > {SCHEMA_FILE}"
    )


def test_committed_spec_reference_is_generated_from_the_schema() -> None:
    committed = (ROOT / REFERENCE_FILE).read_text()
    assert committed == schema_text(markdown=True), (
        f"{REFERENCE_FILE} is stale; regenerate it: assembler schema --markdown > {REFERENCE_FILE}"
    )


def test_schema_command_prints_the_committed_files(capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["schema"]) == 0
    assert json.loads(capsys.readouterr().out) == json.loads((ROOT / SCHEMA_FILE).read_text())
    assert main(["schema", "--markdown"]) == 0
    assert capsys.readouterr().out.startswith("# Spec reference\n")


def test_every_field_of_every_spec_kind_has_a_docstring_and_a_reference_row() -> None:
    schema = spec_json_schema()
    reference = markdown_reference(schema)
    sections = {s.split("\n", 1)[0]: s for s in reference.split("\n## ")[1:]}
    for model_name, model in schema["$defs"].items():  # type: ignore[attr-defined]
        assert model_name in sections, f"no section for {model_name}"
        for field, field_schema in model["properties"].items():
            description = field_schema.get("description", "")
            assert description, f"{model_name}.{field} has no docstring"
            row = next(
                line for line in sections[model_name].splitlines() if line.startswith(f"| `{field}` |")
            )
            assert row.endswith(f"| {' '.join(description.split())} |")


def test_reference_shows_types_defaults_and_required_fields() -> None:
    reference = schema_text(markdown=True)
    assert (
        "| `armature` | number ≥ 0.0 or list of number ≥ 0.0 or [InverseIndexRule](#inverseindexrule) or null "
        '| `{"inverse_index": 5.0}` |' in reference
    )
    assert (
        "| `mjcf` | string (not empty) or null | this or `urdf` **required** unless `extends` |" in reference
    )
    assert (
        "| `urdf` | string (not empty) or null | this or `mjcf` **required** unless `extends` |" in reference
    )
    assert "| `important_sites` | mapping of string to string | `{}` |" in reference
    assert '| `eef_bodies` | mapping of (`"right"` or `"left"`) to string | `{}` |' in reference


@pytest.mark.parametrize(
    ("schema", "text"),
    [
        ({"type": "array", "prefixItems": [{"type": "number"}] * 3}, "[number, number, number]"),
        ({"anyOf": [{"type": "integer", "minimum": 0}, {"type": "null"}]}, "integer ≥ 0 or null"),
        (
            {"type": "array", "items": {"anyOf": [{"type": "string"}, {"type": "null"}]}},
            "list of (string or null)",
        ),
        ({"type": "string", "minLength": 10}, "string (at least 10 characters)"),
        ({"$ref": "#/$defs/JointDefaults"}, "[JointDefaults](#jointdefaults)"),
    ],
)
def test_types_read_as_a_person_says_them(schema: dict[str, object], text: str) -> None:
    assert type_text(schema) == text


def test_a_spec_that_extends_another_needs_only_its_name() -> None:
    validator = jsonschema.Draft202012Validator(spec_json_schema())
    assert validator.is_valid({"name": "Soft", "extends": "Sparrow7", "joint_defaults": {"damping": 0.3}})
    assert not validator.is_valid({"name": "Soft", "joint_defaults": {"damping": 0.3}})  # no mjcf
    assert not validator.is_valid({"name": "Soft", "extends": "Sparrow7", "dampng": 0.3})


@pytest.mark.parametrize("path", SHIPPED_SPECS, ids=lambda p: str(p.relative_to(ROOT)))
def test_shipped_spec_points_editors_at_the_committed_schema(path: Path) -> None:
    first_line = path.read_text().splitlines()[0]
    match = SCHEMA_LINE.match(first_line)
    assert match, (
        f"{path.relative_to(ROOT)} must start with '# yaml-language-server: $schema=<relative path>'"
    )
    assert (path.parent / match.group(1)).resolve() == (ROOT / SCHEMA_FILE).resolve()


@pytest.mark.parametrize("path", SHIPPED_SPECS, ids=lambda p: str(p.relative_to(ROOT)))
def test_shipped_spec_is_valid_for_the_editor(path: Path) -> None:
    validator = jsonschema.Draft202012Validator(json.loads((ROOT / SCHEMA_FILE).read_text()))
    errors = [error.message for error in validator.iter_errors(yaml.safe_load(path.read_text()))]
    assert errors == []
