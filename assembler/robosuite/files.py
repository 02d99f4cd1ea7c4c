"""MJCF text written for robosuite, which reads models from files: files named by their content in
the cache's ``robosuite/`` folder (:mod:`assembler.cache.content`), kept across processes and
verified on every use: a warm ``robosuite.make`` writes nothing, and a part file edited in the cache
is made again, never simulated. With the cache off they go to a folder of the process's own."""

from __future__ import annotations

from assembler.cache.content import PARTS, content_folder, text_file


def written_file(text: str) -> str:
    """The path of a file holding ``text`` (written only when no whole one is there)."""
    return str(text_file(content_folder(PARTS), text, ".xml"))
