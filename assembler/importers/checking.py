"""Whether the spec ``assembler new`` wrote validates and builds as written: it is registered and
compiled (with its default base and grippers) as ``assembler validate --compile`` would, and what
stops it is returned as the user's lines (one per problem), never raised."""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from assembler.errors import AssemblerError
from assembler.registry.catalog import register_specs, register_with_siblings
from assembler.registry.instances import assemble, create_base, create_gripper


def build_problems(spec_path: Path, kind: str, jaw_paths: Sequence[Path] = ()) -> list[str]:
    """The lines saying why the spec at ``spec_path`` does not build, or none when it builds. It is
    registered with the specs beside it, as ``assembler build SPEC`` registers it; the jaw specs
    ``new`` wrote beside it (``jaw_paths``: a bimanual robot's two) are registered first, so that a
    broken spec beside them hides no jaw."""
    try:
        for jaw_path in jaw_paths:
            register_specs(jaw_path)
        (registered,) = register_with_siblings([spec_path])
        if kind == "gripper":
            create_gripper(registered.__name__).compile_alone()
        elif kind == "base":
            create_base(registered.__name__).compile_alone()
        else:
            assemble(registered.__name__).get_model()
    except AssemblerError as error:
        return [str(problem) for problem in error.problems]
    return []
