"""``compare(a, b)``: the spec fields and compiled-model values that differ between two specs."""

from __future__ import annotations

from dataclasses import dataclass

from assembler.tools.diff.model_diff import ModelDiff, model_changes
from assembler.tools.diff.sides import Side, load_side
from assembler.tools.diff.spec_diff import FieldChange, spec_changes


@dataclass(frozen=True)
class Comparison:
    """Two sides and what differs between them."""

    before: Side
    after: Side
    spec: list[FieldChange]
    model: ModelDiff

    @property
    def identical(self) -> bool:
        """True when neither the specs nor the compiled models differ."""
        return not self.spec and self.model.empty


def compare(before: str, after: str) -> Comparison:
    """Load both sides (spec file, ``file@revision`` or registered name), compile both, compare."""
    old, new = load_side(before), load_side(after)
    return Comparison(
        before=old,
        after=new,
        spec=spec_changes(old.spec, new.spec),
        model=model_changes(old.compile(), new.compile()),
    )
