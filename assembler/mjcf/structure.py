"""Facts about a part's MJCF structure that composition relies on (its single, named root body)."""

from __future__ import annotations

from assembler.errors import MjcfError
from assembler.files.paths import display_path
from assembler.mjcf.source import MjcfSource


def root_body_name(source: MjcfSource) -> str:
    """The single body directly in the file's worldbody; the part's root."""
    roots = [body.name for body in source.pristine.worldbody.bodies]
    if len(roots) != 1:
        found = ", ".join(repr(name or "(unnamed)") for name in roots) or "none"
        raise MjcfError(
            f"{display_path(source.path)}: expected exactly one body in <worldbody>, found "
            f"{len(roots)} ({found}); wrap the parts in one root body"
        )
    if not roots[0]:
        raise MjcfError(f"{display_path(source.path)}: the root body needs a name")
    return str(roots[0])
