"""The compiled-model cache's storage: an assembly whose inputs have not changed loads MuJoCo's
binary model from disk instead of compiling its meshes again.

The compile service that uses it is :mod:`assembler.compiler.service`; a lookup hashes the build
inputs (:mod:`assembler.cache.key`), finds the entry (:mod:`assembler.cache.store`) and checks
the files it was compiled from (:mod:`assembler.cache.dependencies`); nothing is assembled on a
hit. A model loaded again and again in one process is copied from memory
(:mod:`assembler.cache.memory`). ``--no-cache`` (``cache=False``) or ``ASSEMBLER_NO_CACHE=1`` turn it
off; :mod:`assembler.files.cache_location` has the other knobs.
"""

from assembler.cache.build_inputs import BuildInputs, JointEdit, PartInputs
from assembler.cache.store import CacheInfo, ModelStore
from assembler.files.cache_location import cache_dir, cache_disabled

__all__ = [
    "BuildInputs",
    "CacheInfo",
    "JointEdit",
    "ModelStore",
    "PartInputs",
    "cache_dir",
    "cache_disabled",
]
