"""The JSON Schema of every spec file kind, for editors and review bots, and the spec reference
(``docs/spec.md``) rendered from it: both generated from the schema models' field docstrings.
Pure text out; ``assembler schema`` prints it."""

from __future__ import annotations

import json
from typing import Any

from pydantic.json_schema import GenerateJsonSchema, models_json_schema
from pydantic_core import core_schema

from assembler.spec.schema.base_spec import BaseSpec
from assembler.spec.schema.experiment import ExperimentSpec
from assembler.spec.schema.gripper import GripperSpec
from assembler.spec.schema.reference import markdown_reference
from assembler.spec.schema.robot import RobotSpec
from assembler.spec.schema.scene import SceneSpec

SCHEMA_FILE = "schema/robot-spec.schema.json"
"""Where the repository keeps the JSON Schema (``assembler schema > schema/robot-spec.schema.json``)."""

REFERENCE_FILE = "docs/spec.md"
"""Where the repository keeps the spec reference (``assembler schema --markdown > docs/spec.md``)."""

ALWAYS_REQUIRED: tuple[str, ...] = ("name", "kind")
"""Fields a spec must write even when it ``extends`` another; the parent supplies the rest."""

MODEL_FILE_FIELDS: tuple[str, ...] = ("mjcf", "urdf")
"""A part spec gives exactly one of these (unless it ``extends`` another)."""


class _FactoryDefaults(GenerateJsonSchema):
    """Shows defaults made by ``default_factory`` too, so editors and the reference show every default."""

    def get_default_value(self, schema: core_schema.WithDefaultSchema) -> Any:
        factory = schema.get("default_factory")
        if factory is not None and not schema.get("default_factory_takes_data"):
            return factory()  # type: ignore[call-arg]
        return super().get_default_value(schema)


def _inheritable(model_schema: dict[str, Any]) -> None:
    """A spec that ``extends`` another may leave out what its parent gives (e.g. ``mjcf``)."""
    if "extends" not in model_schema.get("properties", {}):
        return
    required = model_schema.pop("required", [])
    model_schema["if"] = {"required": ["extends"]}
    model_schema["then"] = {"required": [f for f in required if f in ALWAYS_REQUIRED]}
    model_schema["else"] = {"required": required}
    if all(field in model_schema["properties"] for field in MODEL_FILE_FIELDS):
        model_schema["else"]["oneOf"] = [{"required": [field]} for field in MODEL_FILE_FIELDS]


def spec_json_schema() -> dict[str, object]:
    """The JSON Schema of every spec file (robot, base, gripper, scene), for editors and review bots."""
    models = (RobotSpec, BaseSpec, GripperSpec, SceneSpec, ExperimentSpec)
    _, schema = models_json_schema(
        [(m, "validation") for m in models], ref_template="#/$defs/{model}", schema_generator=_FactoryDefaults
    )
    for model_schema in schema.get("$defs", {}).values():
        _inheritable(model_schema)
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "robot-assembler spec",
        "description": "A robot, base, gripper or scene spec; `kind` says which (robot if absent).",
        "anyOf": [{"$ref": f"#/$defs/{m.__name__}"} for m in models],
        **schema,
    }


def schema_text(markdown: bool = False) -> str:
    """Exactly what ``assembler schema`` (or ``--markdown``) prints: the committed files' content."""
    schema = spec_json_schema()
    if markdown:
        return markdown_reference(schema)
    return json.dumps(schema, indent=2) + "\n"
