"""A robot with overrides, answered by patching the cached model of the same robot without them.

``assemble("Panda", overrides={"joint_defaults.frictionloss": 0.3}).get_model()`` used to compile
the whole assembly again, meshes and all, when only a few numbers of the compiled model differ
from the plain Panda's. When the compiled-model cache misses such a robot, and holds the robot
without its overrides (same idn, base, grippers and placement), this module loads that model,
writes what the overrides change (:func:`~assembler.build.patchable.model_patch`) and recomputes
what MuJoCo derives from it (:func:`~assembler.build.derived.apply_patch`): no MJCF is built, no
mesh is read or decoded, nothing is compiled. The result equals a full compile within 1e-10 in
every model field (tests/build/test_patched_api.py).

Anything a patch cannot do (a structural override, ``set_joint_attribute`` edits, the plain robot
not in the cache) is compiled as before; the reason is logged at DEBUG level on the
``assembler.build.patched`` logger, never warned: a compile is the normal answer, not a problem.

The patched model is stored under the variant's own cache key (unless ``store=False``), with the
files of the entry it was patched from (the same files: an override that names another file is
structural). So the next request for the same variant, in this or another process, is a plain
cache hit, answered from its request record without reading the specs, as any robot's is. The
entry holds the patched model, which equals the compiled one within 1e-10, not bit for bit.
"""

from __future__ import annotations

import logging
from dataclasses import replace

from assembler.build.derived import apply_patch
from assembler.build.patch_inputs import Resolved
from assembler.build.patchable import NotPatchable, model_patch
from assembler.build.service import CompiledModel, default_store, entry_key, load_entry
from assembler.cache.dependencies import Dependency, Recorder, verify
from assembler.cache.file_state import Stat
from assembler.mjcf.keyframe import Keyframe
from assembler.models import RobotModel
from assembler.registry.catalog import applied_overrides

LOG = logging.getLogger("assembler.build.patched")


def unpatched_class(cls: type[RobotModel]) -> type[RobotModel]:
    """The robot class ``cls`` was made from by overrides (``with_overrides`` subclasses it), or
    ``cls`` itself when it has none."""
    while applied_overrides(cls) and issubclass(cls.__bases__[0], RobotModel):
        cls = cls.__bases__[0]
    return cls


def _refusal(robot: RobotModel) -> str | None:
    """Why ``robot`` cannot be patched from its plain robot before looking at the cache, or None."""
    if not applied_overrides(type(robot)):
        return "no overrides"
    if robot.joint_edits:
        return "set_joint_attribute edits (not resolved by a patch)"
    return None


def _known_digests(dependencies: list[Dependency]) -> dict[str, Dependency]:
    return {state.path: state for state in dependencies if not state.racy}


def _store(key: str, robot: RobotModel, patched: CompiledModel, base_key: str) -> None:
    """Keep ``patched`` under ``key`` with the files of the entry ``base_key`` it came from."""
    store = default_store()
    entry = store.entry(base_key)
    current = verify(entry.dependencies) if entry is not None else None
    if entry is None or current is None:
        return  # the plain robot's entry went or its files changed meanwhile: nothing is kept
    known = _known_digests(current)

    def digest(path: str, stat: Stat) -> str | None:
        state = known.get(path)
        return state.digest if state is not None and state.stat == stat else None

    earlier = {path: (size, mtime) for path, size, mtime in robot.source.files}
    recorder = Recorder([state.path for state in current], earlier, digest)
    label = " + ".join(part.name for part in [robot, *robot.models]) + f" (patched from {entry.label})"
    store.save(key, patched.model, recorder, label)


def patched_variant(robot: RobotModel, key: str, store: bool = True) -> CompiledModel | None:
    """``robot``'s model patched from the cached model of its plain robot (see the module), kept under
    ``key`` (its own entry) with ``store``; None, with the reason logged, when it must be compiled."""
    reason = _refusal(robot)
    if reason is not None:
        LOG.debug("%s compiled: %s", robot.name, reason)
        return None
    plain = unpatched_class(type(robot))(idn=robot.idn)
    base_key = entry_key(replace(robot.build_inputs(), robot=plain.part_inputs()))
    model = load_entry(base_key, counted=False) if base_key is not None else None
    if base_key is None or model is None:
        LOG.debug("%s compiled: the robot without its overrides is not in the model cache", robot.name)
        return None
    try:
        patch = model_patch(model, Resolved.of(plain), Resolved.of(robot))
    except NotPatchable as error:
        LOG.debug("%s compiled: %s", robot.name, error)
        return None
    apply_patch(model, patch)  # load_entry's model is this caller's own (a copy when kept in memory)
    patched = CompiledModel(model, Keyframe.of(model))
    if store:
        _store(key, robot, patched, base_key)
    LOG.debug("%s patched from its plain robot's cached model: %s", robot.name, ", ".join(patch.fields))
    return patched
