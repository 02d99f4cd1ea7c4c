"""Robots as batches of MuJoCo Warp worlds: one compile, one patched world per variant.

Needs the ``warp`` extra (``pip install -e '.[warp]'``); importing this package without it raises
an ImportError that says so.
"""

from assembler.warp.batch import WarpBatch, batchable_fields, put_variants

__all__ = ["WarpBatch", "batchable_fields", "put_variants"]
