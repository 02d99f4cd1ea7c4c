"""The spec reference (``docs/spec.md``): every field of every spec kind, rendered from the JSON Schema.

The page is made from the same JSON Schema editors read (``assembler schema``), whose descriptions
are the schema models' field docstrings, so documentation is never written twice. Pure text in,
text out: no file I/O here (``assembler schema --markdown`` prints it).
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping
from typing import Any

Schema = Mapping[str, Any]

HEADER = """\
# Spec reference

<!-- Generated from the schema's field docstrings by `assembler schema --markdown > docs/spec.md`.
     Do not edit by hand: tests/spec/test_schema_docs.py keeps it in sync. -->

A spec file is one YAML mapping; unknown keys are errors. `kind` says what the file describes
(a robot when it is absent). A spec that `extends` another needs only `name` (and `kind`): the
parent gives every field it leaves out. Editors check and complete spec files that start with
`# yaml-language-server: $schema=<path to schema/robot-spec.schema.json>`, the schema this page
is generated from.
"""


def _json(value: Any) -> str:
    return json.dumps(value, separators=(", ", ": "))


def _cell(text: str) -> str:
    """Text that stays inside one Markdown table cell."""
    return " ".join(text.split()).replace("|", "\\|")


def _ref_name(reference: str) -> str:
    return reference.rsplit("/", 1)[-1]


def _link(name: str) -> str:
    return f"[{name}](#{name.lower()})"


def _number_text(schema: Schema) -> str:
    text = "integer" if schema.get("type") == "integer" else "number"
    bounds = [
        (symbol, schema[key])
        for key, symbol in (("exclusiveMinimum", ">"), ("minimum", "≥"), ("exclusiveMaximum", "<"))
        if key in schema
    ]
    bounds += [("≤", schema["maximum"])] if "maximum" in schema else []
    return " ".join([text, *(f"{symbol} {_json(value)}" for symbol, value in bounds)])


def _string_text(schema: Schema) -> str:
    limits = []
    if "pattern" in schema:
        limits.append(f"matching `{schema['pattern']}`")
    if schema.get("minLength") == 1:
        limits.append("not empty")
    elif "minLength" in schema:
        limits.append(f"at least {schema['minLength']} characters")
    if "maxLength" in schema:
        limits.append(f"at most {schema['maxLength']} characters")
    return "string" + (f" ({', '.join(limits)})" if limits else "")


def _part(schema: Schema) -> str:
    """A type inside another (a list's items, a mapping's keys or values), in parentheses if compound."""
    text = type_text(schema)
    return f"({text})" if _has_top_level_or(text) else text


def _has_top_level_or(text: str) -> bool:
    depth = 0
    for index, char in enumerate(text):
        depth += (char in "([") - (char in ")]")
        if depth == 0 and text.startswith(" or ", index):
            return True
    return False


def type_text(schema: Schema) -> str:
    """A JSON Schema type as a reader says it, e.g. ``list of number ≥ 0 or null``."""
    if "$ref" in schema:
        return _link(_ref_name(schema["$ref"]))
    if "anyOf" in schema:
        return " or ".join(dict.fromkeys(type_text(option) for option in schema["anyOf"]))
    if "const" in schema:
        return f"`{_json(schema['const'])}`"
    if "enum" in schema:
        return " or ".join(f"`{_json(value)}`" for value in schema["enum"])
    kind = schema.get("type")
    if kind == "array":
        if "prefixItems" in schema:
            return "[" + ", ".join(_part(item) for item in schema["prefixItems"]) + "]"
        text = f"list of {_part(schema.get('items', {}))}"
        return text + (f" (at least {schema['minItems']})" if "minItems" in schema else "")
    if kind == "object":
        keys = _part(schema["propertyNames"]) if "propertyNames" in schema else "string"
        values = schema.get("additionalProperties")
        return f"mapping of {keys} to {_part(values)}" if isinstance(values, Mapping) else "mapping"
    if kind in ("number", "integer"):
        return _number_text(schema)
    if kind == "string":
        return _string_text(schema)
    if kind in ("boolean", "null"):
        return str(kind)
    return "any value"


def _default_text(name: str, field: Schema, model: Schema) -> str:
    alternatives = [choice["required"][0] for choice in model.get("else", {}).get("oneOf", [])]
    if name in alternatives:
        others = " or ".join(f"`{a}`" for a in alternatives if a != name)
        return f"this or {others} **required** unless `extends`"
    if "default" in field:
        return f"`{_json(field['default'])}`"
    always = model.get("then", {}).get("required", model.get("required", []))
    if name in always:
        return "**required**"
    if name in model.get("else", {}).get("required", []):
        return "**required** unless `extends`"
    return "(none)"


def _models_in_order(schema: Schema) -> Iterator[str]:
    """The spec kinds first, then each nested object where it is first used (breadth first)."""
    queue = [_ref_name(option["$ref"]) for option in schema.get("anyOf", []) if "$ref" in option]
    seen: set[str] = set()
    while queue:
        name = queue.pop(0)
        if name in seen:
            continue
        seen.add(name)
        yield name
        queue += [_ref_name(ref) for ref in _refs(schema["$defs"][name].get("properties", {}))]


def _refs(value: Any) -> Iterator[str]:
    if isinstance(value, dict):
        if "$ref" in value:
            yield value["$ref"]
        for inner in value.values():
            yield from _refs(inner)
    elif isinstance(value, list):
        for inner in value:
            yield from _refs(inner)


def model_section(name: str, model: Schema) -> str:
    """One object's heading, description and field table."""
    rows = [
        f"| `{field_name}` | {_cell(type_text(field))} | {_cell(_default_text(field_name, field, model))} "
        f"| {_cell(field.get('description', ''))} |"
        for field_name, field in model.get("properties", {}).items()
    ]
    return "\n".join(
        [
            f"## {name}",
            "",
            " ".join(model.get("description", "").split()),
            "",
            "| Field | Type | Default | Description |",
            "| --- | --- | --- | --- |",
            *rows,
        ]
    )


def markdown_reference(schema: Schema) -> str:
    """The whole reference page for ``schema`` (as printed by ``assembler schema``), ending in a newline."""
    names = list(_models_in_order(schema))
    kinds = [_ref_name(option["$ref"]) for option in schema.get("anyOf", []) if "$ref" in option]
    index = "Spec kinds: " + ", ".join(_link(n) for n in kinds) + ". Nested objects: "
    index += ", ".join(_link(n) for n in names if n not in kinds) + "."
    sections = [model_section(name, schema["$defs"][name]) for name in names]
    return "\n\n".join([HEADER.rstrip("\n"), index, *sections]) + "\n"
