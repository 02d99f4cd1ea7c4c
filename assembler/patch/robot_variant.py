"""A robot with overrides, answered by patching the cached model of the same robot without them.

``assemble("Panda", overrides={"joint_defaults.frictionloss": 0.3}).get_model()`` used to compile
the whole assembly again, meshes and all, when only a few numbers of the compiled model differ
from the plain Panda's. When the compiled-model cache misses such a robot, and holds the robot
without its overrides (same idn, base, grippers and placement), this module loads that model,
writes what the overrides change (:func:`~assembler.patch.patchable.model_patch`) and recomputes
what MuJoCo derives from it (:func:`~assembler.patch.derived.apply_patch`): no MJCF is built, no
mesh is read or decoded, nothing is compiled. The result equals a full compile within 1e-10 in
every model field (tests/patch/test_patched_api.py).

``get_xml()`` and ``save()`` of such a robot are always answered the same way, the cache on or off:
the plain robot's emitted XML (from its cache entry, else compiled for it) with the patch's values
written into the attributes that hold them (:mod:`assembler.patch.xml_edits`), which MuJoCo loads to
the full compile's model. So a written file's bytes depend on the overrides, never on what the cache
held (a compile writes a servo's resolved ``kv`` where the patch keeps its ``dampratio``, and MuJoCo's
writer rounds some numbers: both load to the same model, but a review would see the bytes change).

Anything a patch cannot do (a structural override, ``set_joint_attribute`` edits; for ``get_model()``
the plain robot not in the cache) is compiled as before; the reason is logged at DEBUG level on the
``assembler.patch.robot_variant`` logger, never warned: a compile is the normal answer, not a problem.

A model patched for ``get_model()`` is not stored as a cache entry of its own, whatever ``store``
says (its patch is, a few hundred bytes: :func:`~assembler.patch.derived.keep_patch`): patching it
again costs about what loading a stored entry would (a Panda: ~0.2 s of CPU against ~0.1 s for the
load, measured under load), while storing it costs more than the patch (serialising a Panda's 44 MB
model, mostly its meshes, took 0.17 s of CPU, plus the write) and each such entry would push the
plain robot's entry, the one every variant needs, out of the bounded cache. A variant asked for
again is patched again from the plain robot's entry, which each use keeps recent, by its kept
patch: in a new process, ``assemble(...).get_model()`` of it is then answered from its request
record without reading a spec or importing the schema (:mod:`assembler.answers.deferred`).

A patched XML is stored, with its model, unless ``store`` is False: it is written to a file, and
stored, the same request is answered from the cache next time with no spec read, as a compiled one
is (the entry records the plain robot's files, which it was made from).
"""

from __future__ import annotations

import logging
from dataclasses import replace

import mujoco

from assembler.compiler.compile import compile_and_emit
from assembler.compiler.keyframe import Keyframe
from assembler.compiler.service import CompiledModel
from assembler.compiler.stored import default_store, entry_key, load_entry
from assembler.mjcf.emit import XmlText
from assembler.models import RobotModel
from assembler.patch.derived import ModelPatch, apply_patch, dampratio_rule, keep_patch, kept_model
from assembler.patch.patchable import NotPatchable, model_patch
from assembler.patch.resolved import Resolved, resolve_spec
from assembler.patch.xml_edits import patched_text
from assembler.registry.catalog import applied_overrides

LOG = logging.getLogger("assembler.patch.robot_variant")


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


def _tables(plain: RobotModel, robot: RobotModel) -> tuple[Resolved, Resolved]:
    """The resolved tables of ``plain`` and of ``robot`` (its overrides): the variant's resolved
    against the plain robot's MJCF when its overrides touch only light sections (its own MJCF is
    then not read)."""
    resolved = Resolved.of(plain)
    light = resolve_spec(plain, resolved, robot.spec, applied_overrides(type(robot)))
    return resolved, light if light is not None else Resolved.of(robot)


def _plain_patch(
    robot: RobotModel, with_xml: bool = False, cache: bool = True, store: bool = True
) -> tuple[mujoco.MjModel, ModelPatch, str, str | None] | None:
    """The model of ``robot``'s plain robot, the patch that makes ``robot`` of it, (with
    ``with_xml``; else "") the plain robot's XML, and the plain robot's cache key (None with the
    cache off); None, with the reason logged, when it must be
    compiled. Without ``with_xml`` only the cached model is used (a patch must cost less than the
    compile it saves); with it the plain robot's model and XML come from the cache, else from its
    compile (kept unless ``store`` is False), so the text is the same whatever the cache held."""
    reason = _refusal(robot)
    if reason is not None:
        LOG.debug("%s compiled: %s", robot.name, reason)
        return None
    plain = unpatched_class(type(robot))(idn=robot.idn)
    base_key = _plain_key(robot, plain, cache)
    if with_xml:
        model, xml = _plain_model_and_xml(_equipped_plain(robot), base_key, cache, store)
    else:
        model, xml = load_entry(base_key, counted=False) if base_key is not None else None, ""
    if model is None:
        LOG.debug("%s compiled: the robot without its overrides is not in the model cache", robot.name)
        return None
    try:
        return model, model_patch(model, *_tables(plain, robot)), xml, base_key
    except NotPatchable as error:
        LOG.debug("%s compiled: %s", robot.name, error)
        return None


def _plain_key(robot: RobotModel, plain: RobotModel, cache: bool = True) -> str | None:
    """The cache key of ``robot``'s plain robot ``plain`` (same idn, base, grippers and placement)."""
    return entry_key(replace(robot.build_inputs(), robot=plain.part_inputs()), cache)


def _equipped_plain(robot: RobotModel) -> RobotModel:
    """``robot`` without its overrides, with parts of its base's and grippers' classes and its
    placement: the robot whose key :func:`_plain_key` gives, ready to build."""
    plain = unpatched_class(type(robot))(idn=robot.idn)
    if robot.base is not None:
        plain.add_base(type(robot.base)(idn=robot.base.idn))
    for arm, gripper in getattr(robot, "grippers", {}).items():
        plain.add_gripper(type(gripper)(idn=gripper.idn), arm)  # type: ignore[attr-defined]
    plain.place_as(robot)
    return plain


def _plain_model_and_xml(
    plain: RobotModel, key: str | None, cache: bool, store: bool
) -> tuple[mujoco.MjModel, str]:
    """The plain robot's model and emitted XML: its cache entry's when it holds both, else compiled
    (and kept with ``cache`` and ``store``: every later variant of it is then answered from the cache)."""
    if key is not None:
        xml = default_store().load_xml(key)
        model = load_entry(key, counted=False) if xml is not None else None
        if model is not None and xml is not None:
            return model, xml
    LOG.debug("%s compiled for its variants' XML", plain.name)
    if key is None:  # the cache off: one compile, as plain.get_xml(cache=False) makes it
        model, xml = compile_and_emit(plain.mjspec, plain.assembly_home(), plain.describe(), meshes=False)
        return model, xml
    xml = plain.get_xml(cache=True, store=store)  # compiled and kept: the model below is its load
    return plain.get_model(cache=True, store=store), xml


def patched_variant(robot: RobotModel, store: bool = True) -> CompiledModel | None:
    """``robot``'s model patched from the cached model of its plain robot (see the module), by the
    patch kept for its entry, else by one worked out now (and kept unless ``store`` is False);
    None, with the reason logged, when it must be compiled."""
    key = robot.entry_key  # get_model's key for this robot, set before it asks
    kept = kept_model(key) if key is not None and _refusal(robot) is None else None
    if kept is not None:
        LOG.debug("%s patched from its plain robot's cached model by its kept patch", robot.name)
        return CompiledModel(kept, Keyframe.of(kept))
    found = _plain_patch(robot)
    if found is None:
        return None
    model, patch, _, plain_key = found
    rule = patch.dampratio_rule or dampratio_rule(model, patch.dampratio)  # read off the plain model
    patch = replace(patch, dampratio_rule=rule)
    apply_patch(model, patch)  # load_entry's model is this caller's own (a copy when kept in memory)
    LOG.debug("%s patched from its plain robot's cached model: %s", robot.name, ", ".join(patch.fields))
    if store and key is not None and plain_key is not None:
        keep_patch(key, plain_key, patch)
    return CompiledModel(model, Keyframe.of(model))


def patched_variant_xml(
    robot: RobotModel, cache: bool = True, store: bool = True
) -> tuple[CompiledModel, str] | None:
    """``robot``'s model and MJCF, both from its plain robot's (cached, else compiled): the model
    patched, the text the plain robot's emitted XML with the patch's values written in
    (:mod:`assembler.patch.xml_edits`); None, with the reason logged, when it must be compiled
    (the patch writes what no attribute holds alone: ``bodies:`` scales)."""
    if any(override.path[:1] == ("bodies",) for override in applied_overrides(type(robot))):
        # A body's mass, inertia and sizes are held by no attribute alone: compiled, with no
        # compile of the plain robot first for a text that could not be edited anyway.
        LOG.debug("%s compiled for its XML: not writable as attribute edits (bodies:)", robot.name)
        return None
    found = _plain_patch(robot, with_xml=True, cache=cache, store=store)
    if found is None:
        return None
    model, patch, xml, plain_key = found
    text = patched_text(model, XmlText(xml), patch)
    if text is None:
        LOG.debug("%s compiled for its XML: not writable as attribute edits", robot.name)
        return None
    apply_patch(model, patch)
    LOG.debug("%s written from its plain robot's XML: %s", robot.name, ", ".join(patch.fields))
    key = robot.entry_key
    if store and key is not None and plain_key is not None:  # a file written: next time from the cache
        default_store().save_patched(key, model, robot.name, text, plain_key)
    return CompiledModel(model, Keyframe.of(model)), text
