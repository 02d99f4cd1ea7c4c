"""The cache key of an assembled robot: a hash of everything that defines it, computed without
assembling or compiling anything (ccache's "direct mode").

The key covers each part's validated spec (which already holds the fields of every spec it
extends), its class and idn, the joint values the build will write (so ``set_joint_attribute``
calls count), the robot's placement, the assembler's own code and MuJoCo's version. The files
the compile reads are not in the key: the entry lists them (see :mod:`assembler.cache.dependencies`)
and a lookup checks them.

Only robots whose every part is a class made from a spec are cached: a hand-written subclass may
override any build step, and its Python code is not something the key can see.
"""

from __future__ import annotations

import functools
import hashlib
import json
from pathlib import Path
from typing import TYPE_CHECKING, Any

import mujoco

if TYPE_CHECKING:
    from assembler.models.part import PartModel
    from assembler.models.robot_model import RobotModel

FORMAT = 1
"""Version of the entry layout and of the key's contents; bump it when either changes."""

_PACKAGE = Path(__file__).resolve().parent.parent


@functools.lru_cache(maxsize=1)
def code_fingerprint() -> str:
    """The assembler's version and a digest of its Python sources' names, sizes and times.

    The version alone is not enough: an editable install changes the code without changing the
    version, and a stale model after a code change would be a silent wrong answer. Stat rather
    than content keeps this under a millisecond; an edit or a new install changes the times.
    """
    from assembler import __version__  # here, not at import: assembler imports this module

    digest = hashlib.blake2b(digest_size=16)
    for path in sorted(_PACKAGE.rglob("*.py")):
        stat = path.stat()
        digest.update(f"{path.relative_to(_PACKAGE)}:{stat.st_size}:{stat.st_mtime_ns};".encode())
    return f"{__version__}+{digest.hexdigest()}"


def spec_made(part: PartModel) -> bool:
    """True for a part whose class and every base class is the assembler's (made from a spec)."""
    return all(cls is object or cls.__module__.startswith("assembler.") for cls in type(part).__mro__)


def _part(part: PartModel) -> dict[str, Any]:
    return {
        "classes": [f"{cls.__module__}.{cls.__qualname__}" for cls in type(part).__mro__],
        "spec": part.spec.model_dump(mode="json"),
        "source": str(part.source.path),  # package:// resolves per environment
        "idn": repr(part.idn),
        "joints": {
            name: {attribute: value.value for attribute, value in sorted(values.items())}
            for name, values in part.joint_values.items()
        },
    }


def _array(values: Any) -> list[float] | None:
    return None if values is None else [float(v) for v in values]


def robot_key(robot: RobotModel) -> str | None:
    """The key of ``robot`` as it would be assembled now, or None when it cannot be cached."""
    grippers: dict[str, PartModel] = dict(getattr(robot, "grippers", {}))
    parts: list[PartModel] = [robot, *robot.models]
    if not all(spec_made(part) for part in parts):
        return None
    material = {
        "format": FORMAT,
        "assembler": code_fingerprint(),
        "mujoco": mujoco.__version__,
        "robot": _part(robot),
        "base": _part(robot.base) if robot.base is not None else None,
        "grippers": {arm: _part(gripper) for arm, gripper in grippers.items()},
        "root_pos": _array(robot._root_pos),
        "root_quat": _array(robot._root_quat),
    }
    text = json.dumps(material, sort_keys=True, separators=(",", ":"))
    return hashlib.blake2b(text.encode(), digest_size=20).hexdigest()
