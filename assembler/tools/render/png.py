"""PNG encoding with the standard library only (zlib and struct), for 8-bit RGB images.

Each row is filtered with whichever of PNG's None, Sub or Up filters gives the smallest sum of
absolute byte values (the heuristic the PNG specification recommends), which roughly halves the
file size of rendered pictures compared with no filtering. All three filters read the original
bytes only, so they are computed for every row at once with numpy.
"""

from __future__ import annotations

import struct
import zlib

import numpy as np
from numpy.typing import NDArray

SIGNATURE = b"\x89PNG\r\n\x1a\n"
COLOR_TYPE_RGB = 2
FILTER_NONE, FILTER_SUB, FILTER_UP = 0, 1, 2


def _chunk(kind: bytes, payload: bytes) -> bytes:
    """One PNG chunk: length, type, data and the CRC of type and data."""
    return struct.pack(">I", len(payload)) + kind + payload + struct.pack(">I", zlib.crc32(kind + payload))


def _filtered_rows(pixels: NDArray[np.uint8]) -> bytes:
    """Every scanline prefixed with its filter byte, the filter chosen per row."""
    height, width, channels = pixels.shape
    raw = pixels.reshape(height, width * channels).astype(np.int16)
    left = np.zeros_like(raw)
    left[:, channels:] = raw[:, :-channels]
    above = np.zeros_like(raw)
    above[1:] = raw[:-1]
    candidates = np.stack([raw, raw - left, raw - above]) & 0xFF  # None, Sub, Up (mod 256)
    signed = np.where(candidates > 127, 256 - candidates, candidates)  # |byte as int8|
    choice = np.argmin(signed.sum(axis=2), axis=0)  # per row
    rows = candidates[choice, np.arange(height)].astype(np.uint8)
    return bytes(np.concatenate([choice.astype(np.uint8)[:, None], rows], axis=1).tobytes())


def encode_png(pixels: NDArray[np.uint8]) -> bytes:
    """An ``(height, width, 3)`` uint8 RGB array as the bytes of a PNG file."""
    if pixels.ndim != 3 or pixels.shape[2] != 3 or pixels.dtype != np.uint8:
        raise ValueError(f"expected an (height, width, 3) uint8 array, got {pixels.shape} {pixels.dtype}")
    height, width, _ = pixels.shape
    header = struct.pack(">IIBBBBB", width, height, 8, COLOR_TYPE_RGB, 0, 0, 0)
    data = zlib.compress(_filtered_rows(np.ascontiguousarray(pixels)), level=9)
    return SIGNATURE + _chunk(b"IHDR", header) + _chunk(b"IDAT", data) + _chunk(b"IEND", b"")
