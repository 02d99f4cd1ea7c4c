"""Semantic diff of robot specs: the fields that changed and what changed in the compiled model.

``compare(a, b)`` takes spec files, registered names or ``file@revision``; ``FORMATS`` renders the
result as text, Markdown or JSON. Neither side is registered, so two versions of one robot can be
compared while the registered one stays as it is.
"""

from assembler.tools.diff.compare import Comparison, compare
from assembler.tools.diff.formats import FORMATS

__all__ = ["FORMATS", "Comparison", "compare"]
