"""The one compile path: an assembly (a MuJoCo spec, its home pose, the files it read) in, a compiled
model with its ``home`` keyframe out (:mod:`.compile`; the keyframe itself in :mod:`.keyframe`), from
the compiled-model cache when nothing it read changed (:mod:`.service`, whose lookup alone is
:mod:`.stored`). It takes values, never models: models call down into it from ``get_model()``."""

from __future__ import annotations

from collections.abc import Callable
from types import ModuleType

variant_patcher: Callable[[], ModuleType] | None = None
"""Loads the module answering a cache miss of a robot with overrides by patching its plain robot's
cached model (:mod:`assembler.patch.robot_variant`: ``patched_variant(robot)``,
``patched_variant_xml(robot)``). The patcher reads the registry and the model classes, which sit
above the compiler and the models, so the package root wires it in here (``assembler/__init__.py``)
and a model asks for it without naming it. None: every miss compiles."""
