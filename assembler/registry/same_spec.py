"""When a spec file is the same spec as a registered one, so that registering it is no duplicate.

After ``pip install .`` the shipped specs are registered from the installed package's copy
(``site-packages/assembler/_shipped/specs``); the clone's ``specs/`` holds the same files, and
``assembler validate specs/`` registers them again. Two specs of one name are the same spec when
their validated fields are equal and their MJCF files have the same content (a ``package://``
reference compares as written): the file the user named then takes the registered copy's place,
so every later message points at it. Two different specs of one name stay an error naming both.
"""

from __future__ import annotations

import hashlib
from typing import Any

from assembler.files.paths import PACKAGE_SCHEME, shipped_specs_dir
from assembler.files.regular import open_regular
from assembler.spec.documents import LoadedSpec

_MJCF = "mjcf"


def _content(reference: Any) -> Any:
    """An MJCF reference as what it reads: a file's content digest, else the reference itself."""
    if not isinstance(reference, str) or reference.startswith(PACKAGE_SCHEME):
        return reference
    try:
        with open_regular(reference) as stream:
            return "sha256:" + hashlib.sha256(stream.read()).hexdigest()
    except (OSError, ValueError):  # not there (yet): compare the paths
        return reference


def _fingerprint(loaded: LoadedSpec[Any]) -> dict[str, Any]:
    data: dict[str, Any] = loaded.spec.model_dump(mode="json")
    data[_MJCF] = _content(data.get(_MJCF))
    return data


def same_spec(existing: type, loaded: LoadedSpec[Any]) -> bool:
    """True when ``loaded`` describes what the registered class ``existing`` was made from."""
    registered = getattr(existing, "loaded", None)
    if registered is None:
        return False  # a class written in Python
    return bool(_fingerprint(registered) == _fingerprint(loaded))


def shipped_note(existing: type) -> str:
    """What to add to a duplicate-name error when the registered copy is a shipped spec."""
    registered = getattr(existing, "loaded", None)
    path = registered.document.path if registered is not None else None
    if path is None or not path.is_relative_to(shipped_specs_dir().resolve()):
        return ""
    return (
        " (the installed package's copy; to change a shipped spec in a clone of robot-assembler, "
        'install the clone with pip install -e ".[robosuite]")'
    )
