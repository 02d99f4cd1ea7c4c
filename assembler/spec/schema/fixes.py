"""Declared repairs of an MJCF file we read but do not own (e.g. robosuite's), applied before MuJoCo
parses it. Each repair names the element it touches and says why, so a reviewer sees every
departure from the file as published.
"""

from __future__ import annotations

from pydantic import Field, model_validator

from assembler.spec.schema.common import StrictModel


class MjcfFix(StrictModel):
    """One repair of the MJCF text and the files it includes: exactly one of
    ``keep_first_of_repeated_names``, ``remove``, ``set``, ``delete``."""

    element: str = Field(pattern=r"^[a-z]+$")
    """The XML tag it applies to, on every element with it (``set`` creates a missing one under the root)."""

    why: str = Field(min_length=10)
    """What is wrong with the file and why this repair reproduces the intended model."""

    where: dict[str, str] = Field(default_factory=dict)
    """Only the elements whose attributes have these values (e.g. ``{name: "robot0:mocap"}``); empty:
    every element with the tag."""

    keep_first_of_repeated_names: bool = False
    """Drop later elements whose name repeats an earlier one (MuJoCo refuses repeated names)."""

    remove: list[str] = Field(default_factory=list)
    """Attributes to delete from every such element (e.g. one MuJoCo's schema refuses)."""

    set: dict[str, str] = Field(default_factory=dict)
    """Attributes to set on every such element (e.g. ``{angle: radian}`` on ``compiler``)."""

    delete: bool = False
    """Delete every such element with everything inside it (e.g. a mocap body, and the weld that holds
    a body to it: ``{element: weld, where: {body1: "robot0:mocap"}, delete: true}``)."""

    @model_validator(mode="after")
    def _exactly_one_action(self) -> MjcfFix:
        actions = [bool(self.keep_first_of_repeated_names), bool(self.remove), bool(self.set), self.delete]
        if sum(actions) != 1:
            raise ValueError("give exactly one of keep_first_of_repeated_names, remove, set, delete")
        return self
