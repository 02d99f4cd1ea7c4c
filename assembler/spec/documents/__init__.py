"""Spec documents: YAML read with positions, inheritance, overrides, schema validation.

Every file kind (robot, base, gripper, scene, experiment) goes through this one layer, so each
problem a user causes is reported the same way: ``file:line:col: field.path: message``.
"""

from assembler.spec.documents.inheritance import (
    NoParents,
    Parents,
    Resolver,
    is_file_reference,
)
from assembler.spec.documents.located import LocatedDocument
from assembler.spec.documents.overrides import (
    FIXED_FIELDS,
    Override,
    Overrides,
    apply_overrides,
    blame,
    overridden_spec,
    parse_override,
    parse_overrides,
    parse_path,
)
from assembler.spec.documents.problems import LoadedSpec, validate, validation_problems
from assembler.spec.documents.reading import PATH_FIELDS, read_document, read_validated, resolve_path_fields
from assembler.spec.documents.yaml_reader import parse_yaml, read_yaml_text

__all__ = [
    "FIXED_FIELDS",
    "PATH_FIELDS",
    "LoadedSpec",
    "LocatedDocument",
    "NoParents",
    "Override",
    "Overrides",
    "Parents",
    "Resolver",
    "apply_overrides",
    "blame",
    "is_file_reference",
    "overridden_spec",
    "parse_override",
    "parse_overrides",
    "parse_path",
    "parse_yaml",
    "read_document",
    "read_validated",
    "read_yaml_text",
    "resolve_path_fields",
    "validate",
    "validation_problems",
]
