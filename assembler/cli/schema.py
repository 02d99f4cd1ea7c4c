"""``assembler schema``: the JSON Schema of every spec kind, for editors and review bots."""

from __future__ import annotations

import argparse
import json

from pydantic.json_schema import models_json_schema

from assembler.schema import BaseSpec, GripperSpec, RobotSpec, SceneSpec


def add_parser(commands: argparse._SubParsersAction[argparse.ArgumentParser]) -> None:
    parser = commands.add_parser("schema", help="print the JSON Schema of spec files")
    parser.set_defaults(run=run)


def spec_json_schema() -> dict[str, object]:
    """The JSON Schema of every spec file (robot, base, gripper, scene), for editors and review bots."""
    models = (RobotSpec, BaseSpec, GripperSpec, SceneSpec)
    _, schema = models_json_schema([(m, "validation") for m in models], ref_template="#/$defs/{model}")
    return {
        "$schema": "https://json-schema.org/draft/2020-12/schema",
        "title": "robot-assembler spec",
        "description": "A robot, base, gripper or scene spec; `kind` says which (robot if absent).",
        "anyOf": [{"$ref": f"#/$defs/{m.__name__}"} for m in models],
        **schema,
    }


def run(args: argparse.Namespace) -> int:
    print(json.dumps(spec_json_schema(), indent=2))
    return 0
