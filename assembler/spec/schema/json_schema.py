"""The JSON Schema of every spec file kind, for editors and review bots, and the spec reference
(``docs/spec.md``) rendered from it: both generated from the schema models' field docstrings.
Pure text out; ``assembler schema`` prints it."""

from __future__ import annotations

import ast
import inspect
import itertools
import json
import textwrap
import typing
from collections.abc import Iterator
from typing import Any

from pydantic.json_schema import GenerateJsonSchema, models_json_schema
from pydantic_core import core_schema

from assembler.spec.schema.base_spec import BaseSpec
from assembler.spec.schema.common import StrictModel
from assembler.spec.schema.experiment import ExperimentSpec
from assembler.spec.schema.gripper import GripperSpec
from assembler.spec.schema.motor import MotorSpec
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


def attribute_docstrings(cls: type) -> dict[str, str]:
    """The docstring written under each annotated attribute in ``cls``'s own body (not its bases')."""
    found: dict[str, str] = {}
    definition = ast.parse(textwrap.dedent(inspect.getsource(cls))).body[0]
    if not isinstance(definition, ast.ClassDef):
        return found
    for statement, after in itertools.pairwise(definition.body):
        if (
            isinstance(statement, ast.AnnAssign)
            and isinstance(statement.target, ast.Name)
            and isinstance(after, ast.Expr)
            and isinstance(after.value, ast.Constant)
            and isinstance(after.value.value, str)
        ):
            found[statement.target.id] = inspect.cleandoc(after.value.value)
    return found


def _nested_models(annotation: object) -> Iterator[type[StrictModel]]:
    if isinstance(annotation, type) and issubclass(annotation, StrictModel):
        yield annotation
    for argument in typing.get_args(annotation):
        yield from _nested_models(argument)


def _models_below(models: tuple[type[StrictModel], ...]) -> list[type[StrictModel]]:
    """Every model ``models`` reach through their fields, each after the models it holds."""
    ordered: list[type[StrictModel]] = []
    seen: set[type[StrictModel]] = set()

    def visit(model: type[StrictModel]) -> None:
        if model in seen:  # also ends a model that holds itself
            return
        seen.add(model)
        for field in model.model_fields.values():
            for nested in _nested_models(field.annotation):
                visit(nested)
        ordered.append(model)

    for model in models:
        visit(model)
    return ordered


def _describe_fields(models: tuple[type[StrictModel], ...]) -> None:
    """Give every field of ``models`` (and of the models they hold) its attribute docstring as its
    description, then rebuild their schemas, innermost first.

    Why here and not with pydantic's ``use_attribute_docstrings``: that reads and parses each model
    class's source when the class is made, in every process that imports the schema (~50 ms of a
    first ``assemble``), while only this JSON Schema shows descriptions."""
    below = _models_below(models)
    docstrings: dict[type, dict[str, str]] = {}
    for model in below:
        for name, field in model.model_fields.items():
            if field.description is not None:
                continue
            owner = next(c for c in model.__mro__ if name in c.__dict__.get("__annotations__", {}))
            if owner not in docstrings:
                docstrings[owner] = attribute_docstrings(owner)
            field.description = docstrings[owner].get(name)
    for model in below:
        model.model_rebuild(force=True)


def spec_json_schema() -> dict[str, object]:
    """The JSON Schema of every spec file (robot, base, gripper, motor, scene, experiment), for editors
    and review bots."""
    models = (RobotSpec, BaseSpec, GripperSpec, MotorSpec, SceneSpec, ExperimentSpec)
    _describe_fields(models)
    _, schema = models_json_schema(
        [(m, "validation") for m in models], ref_template="#/$defs/{model}", schema_generator=_FactoryDefaults
    )
    for model_schema in schema.get("$defs", {}).values():
        _inheritable(model_schema)
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "robot-assembler spec",
        "description": "A robot, base, gripper, motor, scene or experiment spec; `kind` says which (robot "
        "if absent).",
        "anyOf": [{"$ref": f"#/$defs/{m.__name__}"} for m in models],
        **schema,
    }


def schema_text(markdown: bool = False) -> str:
    """Exactly what ``assembler schema`` (or ``--markdown``) prints: the committed files' content."""
    schema = spec_json_schema()
    if markdown:
        return markdown_reference(schema)
    return json.dumps(schema, indent=2) + "\n"
