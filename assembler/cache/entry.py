"""One cache entry's manifest: which model file holds the compiled model (and which file its emitted
XML, once asked for), how to recognise each file whole, and the files the model was compiled from.

The manifest is small JSON, written after the model file and moved into place last: it is the
entry's commit point. A model file no manifest names is an orphan (a writer killed between the two
steps, or an entry replaced by another process) and is removed by the store's clean-up.
"""

from __future__ import annotations

import json
import os
from dataclasses import asdict, dataclass
from typing import Any

from assembler.cache.dependencies import Dependency
from assembler.cache.key import FORMAT

MANIFEST_SUFFIX = ".json"
MODEL_SUFFIX = ".mjb"
XML_SUFFIX = ".xml"


@dataclass(frozen=True)
class Entry:
    """A cache entry's manifest."""

    key: str
    """The key the entry answers (also its manifest's file name)."""

    model: str
    """File name of the compiled model (MuJoCo's binary format), in the cache folder."""

    model_bytes: int
    """Exact size of the model file."""

    digest: str
    """The :data:`~assembler.cache.file_state.DIGEST` of the model file's whole content."""

    label: str
    """What was compiled, for people reading the folder (e.g. ``Panda0``)."""

    dependencies: tuple[Dependency, ...]
    """Every file the compile read, as it was then."""

    xml: str = ""
    """File name of the emitted MJCF (``RobotModel.get_xml``), in the cache folder; empty until an
    XML was asked for."""

    xml_bytes: int = 0
    """Exact size of the XML file (its UTF-8 bytes)."""

    xml_digest: str = ""
    """The :data:`~assembler.cache.file_state.DIGEST` of the XML file's whole content."""

    @property
    def manifest(self) -> str:
        """File name of this manifest."""
        return self.key + MANIFEST_SUFFIX

    def to_json(self) -> str:
        """The manifest's text."""
        data: dict[str, Any] = asdict(self)
        data["format"] = FORMAT
        data["dependencies"] = [asdict(d) for d in self.dependencies]
        return json.dumps(data, indent=1)

    @classmethod
    def from_json(cls, text: str) -> Entry:
        """Parse a manifest; ValueError for anything that is not a whole manifest of this format."""
        try:
            data = json.loads(text)
            if data.pop("format") != FORMAT:
                raise ValueError("another format")
            dependencies = tuple(Dependency(**d) for d in data.pop("dependencies"))
            entry = cls(dependencies=dependencies, **data)
        except (KeyError, TypeError, AttributeError) as error:
            raise ValueError(f"not a manifest: {error}") from None
        named_file = entry.model.endswith(MODEL_SUFFIX) and os.sep not in entry.model
        if not named_file or entry.model_bytes <= 0:
            raise ValueError("not a manifest: bad model file")
        if entry.xml and (not entry.xml.endswith(XML_SUFFIX) or os.sep in entry.xml or not entry.xml_digest):
            raise ValueError("not a manifest: bad XML file")
        return entry
